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

// Math functions whose last bit each engine's math library decides (IEEE 754 fixes only + - * /
// and sqrt; abs, min, max, floor, ceil, round, trunc, sign, fround, imul, clz32 are exact).
const nonDeterministicMath = [
  'sin',
  'cos',
  'tan',
  'asin',
  'acos',
  'atan',
  'atan2',
  'sinh',
  'cosh',
  'tanh',
  'asinh',
  'acosh',
  'atanh',
  'hypot',
  'exp',
  'expm1',
  'log',
  'log1p',
  'log2',
  'log10',
  'pow',
  'cbrt',
];
const deterministicMath =
  'The engine steps bit-identically in every JavaScript engine: use src/math/trigonometry.ts ' +
  '(cosSin, atan2) or src/math/hypot.ts, built from + - * / and sqrt (README: determinism).';

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
        // x ** y is Math.pow.
        {
          selector: "BinaryExpression[operator='**'], AssignmentExpression[operator='**=']",
          message: deterministicMath,
        },
      ],
    },
  },
  {
    // The kernel too: the JavaScript passes and the WebAssembly kernel stay bit for bit the same.
    files: ['packages/engine/src/**/*.ts', 'packages/engine/wasm/**/*.ts'],
    rules: {
      // Each JavaScript engine has its own math library, so these differ in the last bit from
      // one engine to another; the step uses src/math/trigonometry.ts and hypot.ts instead.
      'no-restricted-properties': [
        'error',
        ...nonDeterministicMath.map((property) => ({
          object: 'Math',
          property,
          message: deterministicMath,
        })),
      ],
    },
  },
  ...layerRules,
);
