import {
  setProxyFromCapsule,
  setProxyFromCircle,
  setProxyFromPolygon,
  setProxyFromSegment,
  type DistanceProxy,
} from '../collision/distance.ts';
import type { Geometry } from './shape.ts';

/** Fills a GJK proxy (core vertices plus radius, body frame) from a shape's geometry. */
export function setGeometryProxy(proxy: DistanceProxy, g: Geometry): DistanceProxy {
  if (g.kind === 'circle') return setProxyFromCircle(proxy, g);
  if (g.kind === 'polygon') return setProxyFromPolygon(proxy, g);
  if (g.kind === 'capsule') return setProxyFromCapsule(proxy, g);
  return setProxyFromSegment(proxy, g);
}

/** Fills a GJK proxy from a shape. */
export function setShapeProxy(
  proxy: DistanceProxy,
  shape: { readonly geometry: Geometry },
): DistanceProxy {
  return setGeometryProxy(proxy, shape.geometry);
}
