import { mountShowcase } from './showcase.ts';

mountShowcase(document.getElementById('showcase')!);
