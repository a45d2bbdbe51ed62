/**
 * Init script (page source) that counts layout reads made inside animation-frame callbacks:
 * getBoundingClientRect, getClientRects, getComputedStyle and the offset, client and scroll
 * geometry getters. `window.layoutReads` is the count; `window.frameCallbacks` the frames seen.
 */
export const COUNT_LAYOUT_READS = `
  window.layoutReads = 0;
  window.layoutReadNames = [];
  window.frameCallbacks = 0;
  let inFrame = false;
  const note = (name) => { if (inFrame) { window.layoutReads++; window.layoutReadNames.push(name); } };
  const wrapMethod = (proto, name) => {
    const original = proto[name];
    proto[name] = function (...args) { note(name); return original.apply(this, args); };
  };
  const wrapGetter = (proto, name) => {
    const descriptor = Object.getOwnPropertyDescriptor(proto, name);
    Object.defineProperty(proto, name, {
      ...descriptor,
      get() { note(name); return descriptor.get.call(this); },
    });
  };
  wrapMethod(Element.prototype, 'getBoundingClientRect');
  wrapMethod(Element.prototype, 'getClientRects');
  for (const name of ['offsetWidth', 'offsetHeight', 'offsetLeft', 'offsetTop', 'offsetParent', 'innerText'])
    wrapGetter(HTMLElement.prototype, name);
  for (const name of ['clientWidth', 'clientHeight', 'clientLeft', 'clientTop', 'scrollWidth', 'scrollHeight', 'scrollLeft', 'scrollTop'])
    wrapGetter(Element.prototype, name);
  const computed = window.getComputedStyle;
  window.getComputedStyle = function (...args) { note('getComputedStyle'); return computed.apply(this, args); };
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => raf((time) => {
    inFrame = true;
    window.frameCallbacks++;
    try { callback(time); } finally { inFrame = false; }
  });
`;
