// Side-effect entry: `import '@physical/engine/javascript-kernel'` makes the JavaScript build of
// the contact and joint passes available to every world. A world needs it with `kernel: 'javascript'` (a
// page whose Content-Security-Policy forbids WebAssembly) and, with the default `kernel: 'auto'`,
// where WebAssembly cannot compile or run; elsewhere worlds run the WebAssembly build and an app
// that does not import this file does not ship the JavaScript ones (about 17 KB gzipped for the
// contact passes, 4 KB for the joints', each minified on its own).
import { registerJavaScriptContactKernel } from './dynamics/contact-kernel.ts';
import { createJavaScriptContactKernel } from './dynamics/contact-kernel-javascript.ts';
import { registerJavaScriptJointKernel } from './dynamics/joints/joint-kernel.ts';
import { createJavaScriptJointKernel } from './dynamics/joints/joint-kernel-javascript.ts';

registerJavaScriptContactKernel(createJavaScriptContactKernel);
// The joints' passes, a module of their own (dynamics/joints/joint-kernel.ts), in the same build.
registerJavaScriptJointKernel(createJavaScriptJointKernel);
