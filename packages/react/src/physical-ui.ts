import { PhysicalUI, type PhysicalUIOptions } from '@physical/dom';
import {
  createElement,
  forwardRef,
  useEffect,
  useImperativeHandle,
  useLayoutEffect,
  useRef,
  useState,
  type CSSProperties,
  type ForwardRefExoticComponent,
  type ReactNode,
  type RefAttributes,
  type RefObject,
} from 'react';

// Layout effects do not run in server rendering; this avoids React 18's warning there.
const useClientLayoutEffect = typeof document === 'undefined' ? useEffect : useLayoutEffect;

/**
 * Makes the children of the element in `ref` physical (see `PhysicalUI` of `@physical/dom`)
 * while the component is mounted, and gives them back their layout on unmount. Returns the
 * `PhysicalUI` once mounted (null before, and on the server): call `release()`, `restore()` on it.
 *
 * The options are read when it mounts (give the component a new `key` to rebuild with others),
 * except `reducedMotion`, which follows the prop.
 */
export function usePhysicalUI(
  ref: RefObject<HTMLElement | null>,
  options: PhysicalUIOptions = {},
): PhysicalUI | null {
  const [ui, setUI] = useState<PhysicalUI | null>(null);
  const initial = useRef(options);
  useClientLayoutEffect(() => {
    const container = ref.current;
    if (container === null) return undefined;
    const created = new PhysicalUI(container, initial.current);
    setUI(created);
    return () => {
      created.destroy();
      setUI(null);
    };
  }, [ref]);
  const reducedMotion = options.reducedMotion ?? 'respect';
  useEffect(() => {
    if (ui !== null) ui.reducedMotion = reducedMotion;
  }, [ui, reducedMotion]);
  return ui;
}

/** Props of {@link PhysicalContainer}: the options of `PhysicalUI`, and the element's own. */
export interface PhysicalContainerProps extends PhysicalUIOptions {
  /** The container's tag. Default `"div"`. */
  as?: string;
  /** Called with the `PhysicalUI` once mounted, and with null on unmount. */
  onReady?: (ui: PhysicalUI | null) => void;
  children?: ReactNode;
  id?: string;
  className?: string;
  style?: CSSProperties;
  'aria-label'?: string;
}

/**
 * `<PhysicalContainer>{buttons}</PhysicalContainer>`: a container whose children are physical
 * (they fall when released, drag and throw, and return to their layout), cleaned up on unmount.
 * The ref is the `PhysicalUI` (`ref.current.release()`, `restore()`); children added or removed
 * by React join and leave by themselves.
 */
export const PhysicalContainer: ForwardRefExoticComponent<
  PhysicalContainerProps & RefAttributes<PhysicalUI | null>
> = forwardRef<PhysicalUI | null, PhysicalContainerProps>(function PhysicalContainer(props, ref) {
  const {
    as = 'div',
    onReady,
    children,
    id,
    className,
    style,
    'aria-label': label,
    ...options
  } = props;
  const element = useRef<HTMLElement | null>(null);
  const ui = usePhysicalUI(element, options);
  useImperativeHandle(ref, () => ui!, [ui]);
  const ready = useRef(onReady);
  ready.current = onReady;
  useEffect(() => {
    if (ui === null) return undefined;
    ready.current?.(ui);
    return () => ready.current?.(null);
  }, [ui]);
  return createElement(as, { ref: element, id, className, style, 'aria-label': label }, children);
});
