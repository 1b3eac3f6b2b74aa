// @ts-check
// ESLint with typescript-eslint's type-aware strict rules, trimmed to the code's deliberate patterns.
// The type-aware rules read tsconfig.json (all the TypeScript of the repository); the .mjs/.cjs
// scripts, outside it, get the rules that need no types.
import js from '@eslint/js';
import stylistic from '@stylistic/eslint-plugin';
import { defineConfig } from 'eslint/config';
import globals from 'globals';
import tseslint from 'typescript-eslint';

export default defineConfig(
  {
    ignores: ['dist/', 'demo-dist/', 'docs/api/', 'bench/.build/', 'bench/results/', 'test/artifacts/'],
  },
  js.configs.recommended,
  {
    files: ['**/*.ts'],
    extends: [tseslint.configs.strictTypeChecked],
    languageOptions: {
      parserOptions: { projectService: true, tsconfigRootDir: import.meta.dirname },
    },
    rules: {
      // Values known to be there are asserted so: the location of a uniform the shader declares, a map
      // entry just set, an engine's field once it has booted, the element a page is built with.
      '@typescript-eslint/no-non-null-assertion': 'off',
      // The public API checks the values of untyped JavaScript callers, which its types say cannot occur.
      '@typescript-eslint/no-unnecessary-condition': 'off',
      // Scene objects are narrowed by their type tag rather than instanceof on the per-frame path.
      '@typescript-eslint/no-unsafe-class-instance-assignment': 'off',
      // Short arrows that return a void call (`() => gl.deleteBuffer(b)`) are the code's style.
      '@typescript-eslint/no-confusing-void-expression': 'off',
      // Methods go with their context (Phaser's `on(event, fn, this)`, `forEach(fn, this)`) or are
      // saved to be put back on the same object.
      '@typescript-eslint/unbound-method': 'off',
      // `this` starts walks up a scene tree and is handed out of engine callbacks; no `self = this` closures.
      '@typescript-eslint/no-this-alias': 'off',
      // tsc's noUnusedLocals and noUnusedParameters check this, and count TSDoc `{@link}` references,
      // for which some type imports exist.
      '@typescript-eslint/no-unused-vars': 'off',
      // WebGL's object interfaces are empty, so any value passes for a WebGLTexture: a cast of a wrong
      // value to it says what a test hands over.
      '@typescript-eslint/no-unnecessary-type-assertion': ['error', { typesToIgnore: ['WebGLTexture'] }],
      // Numbers, booleans and nullish values read fine in messages; objects and arrays still do not pass.
      '@typescript-eslint/restrict-template-expressions': [
        'error',
        { allowNumber: true, allowBoolean: true, allowNullish: true },
      ],
    },
  },
  {
    // WebGL's getParameter answers `any`; each field's type says what its parameter holds.
    files: ['src/gl/HostState.ts'],
    rules: { '@typescript-eslint/no-unsafe-assignment': 'off' },
  },
  {
    files: ['test/**/*.ts', 'bench/**/*.ts'],
    rules: {
      // Tests and benches read JSON files and reach into GL contexts and pages as `any`.
      '@typescript-eslint/no-unsafe-argument': 'off',
      '@typescript-eslint/no-unsafe-assignment': 'off',
      '@typescript-eslint/no-unsafe-call': 'off',
      '@typescript-eslint/no-unsafe-member-access': 'off',
      '@typescript-eslint/no-unsafe-return': 'off',
      // Malformed scene files are made by deleting keys and array entries, and with holes.
      '@typescript-eslint/no-array-delete': 'off',
      '@typescript-eslint/no-dynamic-delete': 'off',
      'no-sparse-arrays': 'off',
      // Messages show tuples and pixels as `1,2`, and bad values as String() does.
      '@typescript-eslint/restrict-template-expressions': [
        'error',
        { allowNumber: true, allowBoolean: true, allowNullish: true, allowArray: true },
      ],
      '@typescript-eslint/no-base-to-string': 'off',
      // Test pages keep promise-returning contracts with synchronous bodies.
      '@typescript-eslint/require-await': 'off',
      // Tile rows and fuzzing alphabets are ASCII strings spread into characters.
      '@typescript-eslint/no-misused-spread': 'off',
    },
  },
  {
    files: ['**/*.{js,mjs,cjs}'],
    languageOptions: { globals: { ...globals.node } },
  },
  {
    // The code's layout, as written (no formatter rewrites it): two-space indents, single quotes,
    // semicolons, trailing commas on multi-line lists, no spaces at line ends.
    plugins: { '@stylistic': stylistic },
    rules: {
      '@stylistic/indent': ['error', 2, { SwitchCase: 1, flatTernaryExpressions: false, offsetTernaryExpressions: true, ignoreComments: true }],
      '@stylistic/quotes': ['error', 'single', { avoidEscape: true, allowTemplateLiterals: 'always' }],
      '@stylistic/semi': ['error', 'always'],
      '@stylistic/comma-dangle': ['error', 'always-multiline'],
      '@stylistic/no-trailing-spaces': 'error',
      '@stylistic/eol-last': 'error',
      '@stylistic/keyword-spacing': 'error',
      '@stylistic/space-before-blocks': 'error',
      '@stylistic/arrow-parens': ['error', 'always'],
      '@stylistic/brace-style': ['error', '1tbs', { allowSingleLine: true }],
      '@stylistic/comma-spacing': 'error',
      '@stylistic/no-multiple-empty-lines': ['error', { max: 1 }],
    },
  },
);
