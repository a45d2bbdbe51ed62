// The samples' real source text, bundled by Vite from the modules the gallery runs: what the
// page shows is the file, not a copy.
const files = import.meta.glob<string>('../../../packages/scenes/src/samples/*.ts', {
  query: '?raw',
  import: 'default',
  eager: true,
});

const byId = new Map<string, string>();
for (const [path, text] of Object.entries(files)) {
  byId.set(path.slice(path.lastIndexOf('/') + 1, -'.ts'.length), text);
}

/** The source of sample `id` (its module `packages/scenes/src/samples/<id>.ts`). */
export function sourceOf(id: string): string {
  const text = byId.get(id);
  if (text === undefined) throw new Error(`no source for sample "${id}"`);
  return text;
}
