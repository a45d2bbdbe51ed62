import { icon } from '../ui/Icon.tsx';

// Material Design icon paths (Apache 2.0), inlined as app/icons.tsx does, for the lab tools.
export const StepBackIcon = icon('M6 6h2v12H6zm3.5 6 8.5 6V6z');
export const CopyIcon = icon(
  'M16 1H4c-1.1 0-2 .9-2 2v14h2V3h12V1zm3 4H8c-1.1 0-2 .9-2 2v14c0 1.1.9 2 2 2h11c1.1 0 2-.9 2-2V7c0-1.1-.9-2-2-2zm0 16H8V7h11v14z',
);
export const DownloadIcon = icon('M19 9h-4V3H9v6H5l7 7 7-7zM5 18v2h14v-2H5z');
