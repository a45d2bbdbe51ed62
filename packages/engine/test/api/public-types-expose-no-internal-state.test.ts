import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import ts from 'typescript';
import { beforeAll, describe, expect, it } from 'vitest';
import { PUBLIC_MEMBERS } from './public-members.ts';

// Finding 15: the published declarations (tsconfig.build.json, as `npm run build` emits them, with
// stripInternal) expose no internal state. The build uses isolatedDeclarations, so each file's
// declarations are emitted on their own here (ts.transpileDeclaration: the same output, no type
// check, fast). Each exported class's public members are exactly these;
// a new internal field without its own `@internal` shows up here (e.g. Body.invMass, Joint.invMassB).

/** Public (not private, not protected) member names of every class the declarations hold. */
const classes = new Map<string, string[]>();

beforeAll(() => {
  const configPath = fileURLToPath(new URL('../../tsconfig.build.json', import.meta.url));
  const parsed = ts.getParsedCommandLineOfConfigFile(
    configPath,
    {},
    {
      ...ts.sys,
      onUnRecoverableConfigFileDiagnostic: (d) => {
        throw new Error(ts.flattenDiagnosticMessageText(d.messageText, '\n'));
      },
    },
  )!;
  expect(parsed.options.stripInternal).toBe(true);
  const source = fileURLToPath(new URL('../../src/', import.meta.url));
  const files = readdirSync(source, { recursive: true, encoding: 'utf8' }).filter((f) =>
    f.endsWith('.ts'),
  );
  for (const relative of files) {
    const name = join(source, relative);
    const text = ts.transpileDeclaration(readFileSync(name, 'utf8'), {
      compilerOptions: parsed.options,
      fileName: name,
    }).outputText;
    const file = ts.createSourceFile(name, text, ts.ScriptTarget.Latest, true);
    for (const statement of file.statements) {
      if (!ts.isClassDeclaration(statement) || statement.name === undefined) continue;
      const hidden = ts.ModifierFlags.Private | ts.ModifierFlags.Protected;
      const members = statement.members
        .filter((m) => (ts.getCombinedModifierFlags(m) & hidden) === 0)
        .map((m) => (ts.isConstructorDeclaration(m) ? 'constructor' : m.name!.getText(file)));
      classes.set(statement.name.text, [...new Set(members)]);
    }
  }
}, 120_000);

describe('public types expose no internal state', () => {
  it.each(Object.keys(PUBLIC_MEMBERS))('%s declares only its public API', (name) => {
    const members = classes.get(name);
    expect(members, `no declaration of class ${name}`).toBeDefined();
    expect([...members!].sort()).toEqual(PUBLIC_MEMBERS[name]!.split(' ').filter(Boolean).sort());
  });
});
