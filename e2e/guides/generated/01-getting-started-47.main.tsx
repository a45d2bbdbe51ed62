import { createRoot } from 'react-dom/client';
import * as guide from './01-getting-started-47.tsx';
const [Component] = Object.values(guide) as (() => React.JSX.Element)[];
createRoot(document.getElementById('root')!).render(<Component />);