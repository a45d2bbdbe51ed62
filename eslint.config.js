import js from '@eslint/js';
import tseslint from 'typescript-eslint';

// Engine layers, lowest first. A layer may import only from the layers before it:
// core, math <- geometry <- collision <- dynamics <- world. See ARCHITECTURE.md.
const layers = ['core', 'math', 'geometry', 'collision', 'dynamics', 'world'];
const layerRules = layers.map((layer, index) => {
  const forbidden = layers
    .slice(index + 1)
    .filter((above) => !(layer === 'core' && above === 'math'));
  return {
    files: [`packages/engine/src/${layer}/**/*.ts`],
    rules: {
      '@typescript-eslint/no-restricted-imports': [
        'error',
        {
          patterns: forbidden.map((above) => ({
            group: [`**/${above}/**`],
            message: `${layer}/ is below ${above}/ in the engine's layers and must not import it (ARCHITECTURE.md).`,
            // A body names its World in its public type (body.world) and nothing more.
            allowTypeImports: layer === 'dynamics' && above === 'world',
          })),
        },
      ],
    },
  };
});

export default tseslint.config(
  {
    ignores: [
      '**/dist/**',
      '**/node_modules/**',
      '**/coverage/**',
      '**/generated/**',
      'docs-site/**',
      // Local experiments (git-ignored).
      '.scratch/**',
    ],
  },
  js.configs.recommended,
  ...tseslint.configs.strict,
  {
    rules: {
      '@typescript-eslint/no-non-null-assertion': 'off',
      '@typescript-eslint/consistent-type-imports': 'error',
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_' }],
      'no-console': 'error',
    },
  },
  {
    files: ['packages/engine/src/**/*.ts'],
    rules: {
      // The engine's public surface is index.ts; everything else is internal.
      'no-restricted-syntax': [
        'error',
        { selector: 'ExportAllDeclaration', message: 'List public names explicitly; no export *.' },
      ],
    },
  },
  ...layerRules,
);
