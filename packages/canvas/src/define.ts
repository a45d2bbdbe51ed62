// Side-effect entry: `import '@physical/canvas/define'` registers <physical-canvas>.
import { define } from './element/define-physical-canvas.ts';

define();
