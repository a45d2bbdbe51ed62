// Side-effect entry: `import '@physical/engine/javascript-kernel'` makes the JavaScript build of
// the contact passes available to every world. A world needs it with `kernel: 'javascript'` (a
// page whose Content-Security-Policy forbids WebAssembly) and, with the default `kernel: 'auto'`,
// where WebAssembly cannot compile or run; elsewhere worlds run the WebAssembly build and an app
// that does not import this file does not ship the JavaScript one (about 7 KB gzipped).
import { registerJavaScriptContactKernel } from './dynamics/contact-kernel.ts';
import { createJavaScriptContactKernel } from './dynamics/contact-kernel-javascript.ts';

registerJavaScriptContactKernel(createJavaScriptContactKernel);
