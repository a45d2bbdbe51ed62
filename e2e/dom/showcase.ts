// The package's showcase page, as the browser tests load it.
import { mountShowcase } from '../../packages/dom/examples/showcase.ts';

const ui = mountShowcase(document.getElementById('showcase')!);
Object.assign(window, { ui });
document.documentElement.dataset['ready'] = 'true';
