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
    // The origin goes as "x y" text, which the attribute and the property both parse (React 18
    // writes every prop of a custom element as an attribute: never "[object Object]").
    expect(html).not.toContain('object');
    for (const attribute of [
      'origin="1 2"',
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

describe('<PhysicalCanvas> props React 18 writes as attributes', () => {
  it('leaves `paused` out when false (React 18 would write paused="false": paused)', async () => {
    const { renderToString } = await import('react-dom/server');
    const html = renderToString(
      createElement(PhysicalCanvas, { world: new World(), paused: false, origin: { x: 0, y: 0 } }),
    );
    expect(html).not.toMatch(/paused/);
    expect(html).toContain('origin="0 0"');
  });
});

describe('@physical/react at import', () => {
  it('needs no DOM: the component is defined in Node', () => {
    expect(typeof (globalThis as { window?: unknown }).window).toBe('undefined');
    expect(PhysicalCanvas).toBeDefined();
  });
});
