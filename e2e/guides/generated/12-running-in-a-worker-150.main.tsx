import { createRoot } from 'react-dom/client';
import * as guide from './12-running-in-a-worker-150.tsx';
const [Component] = Object.values(guide) as (() => React.JSX.Element)[];
createRoot(document.getElementById('root')!).render(<Component />);