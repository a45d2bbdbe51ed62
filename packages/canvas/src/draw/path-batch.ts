/**
 * Most items (boxes, arrows, dots) per path when an overlay draws many of them as one path.
 *
 * One fill per item costs a canvas draw each, but one path holding 1,000 items is slow too:
 * measured in headless Chromium (software raster), filling 1,000 arrow heads as one path took
 * about twice as long as in paths of 25 to 200. Paths of this many items keep both costs low.
 */
export const PATH_BATCH_SIZE = 64;
