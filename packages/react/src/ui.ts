// @physical/react/ui: the React binding of Physical UI. A separate entry because it needs
// @physical/dom, an optional peer dependency that apps drawing only a world do not install.

export { PhysicalContainer, usePhysicalUI } from './physical-ui.ts';
export type { PhysicalContainerProps } from './physical-ui.ts';
