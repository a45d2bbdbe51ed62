import { World } from '@physical/engine';
import { createElement } from 'react';
import { describe, expect, it } from 'vitest';
import { PhysicalCanvas } from '@physical/react';

describe('<PhysicalCanvas> on the server', () => {
  it('renders <physical-canvas> with its settings as attributes, without touching window', async () => {
    expect(typeof (globalThis as { window?: unknown }).window).toBe('undefined');
    const { renderToString } = await import('react-dom/server');
    const html = renderToString(
      createElement(PhysicalCanvas, {
        world: new World(),
        pixelsPerMeter: 40,
        origin: { x: 1, y: 2 },
        fit: 'contain',
        viewBox: { x: 0, y: 0, width: 10, height: 5 },
        paused: true,
        debug: ['contacts', 'normals'],
        drag: false,
        'aria-label': 'Falling boxes',
        onBodyTap: () => undefined,
      }),
    );
    expect(html).toMatch(/^<physical-canvas /);
    // The origin is an object: React sets it as a property on the client and leaves it out of
    // the server's HTML (never "[object Object]").
    expect(html).not.toContain('origin=');
    for (const attribute of [
      'pixels-per-meter="40"',
      'fit="contain"',
      'view-box="0 0 10 5"',
      'paused=""',
      'debug="contacts normals"',
      'aria-label="Falling boxes"',
      'drag="off"',
    ]) {
      expect(html).toContain(attribute);
    }
    expect(html).not.toContain('onBodyTap');
  });
});

describe('@physical/react at import', () => {
  it('needs no DOM: the component is defined in Node', () => {
    expect(typeof (globalThis as { window?: unknown }).window).toBe('undefined');
    expect(PhysicalCanvas).toBeDefined();
  });
});
