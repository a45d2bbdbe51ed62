import { createElement } from 'react';
import { describe, expect, it } from 'vitest';
import { PhysicalContainer } from '@physical/react/ui';

describe('<PhysicalContainer> on the server', () => {
  it('renders the container and its children as plain HTML, without touching window', async () => {
    expect(typeof (globalThis as { window?: unknown }).window).toBe('undefined');
    const { renderToString } = await import('react-dom/server');
    const html = renderToString(
      createElement(
        PhysicalContainer,
        { as: 'section', className: 'box', 'aria-label': 'Chips', released: true },
        createElement('button', { type: 'button' }, 'One'),
      ),
    );
    expect(html).toBe(
      '<section class="box" aria-label="Chips"><button type="button">One</button></section>',
    );
  });
});
