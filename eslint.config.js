// @ts-check
// ESLint with typescript-eslint's type-aware strict rules, trimmed to the code's deliberate patterns.
// The type-aware rules read tsconfig.json (all the TypeScript of the repository); the .mjs/.cjs
// scripts, outside it, get the rules that need no types.
import js from '@eslint/js';
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
      // GL objects are asserted non-null where they are made (createBuffer, getUniformLocation of a
      // uniform the shader declares): a null there is a lost context, which the renderer handles as a whole.
      '@typescript-eslint/no-non-null-assertion': 'off',
      // The public API checks the values of untyped JavaScript callers, which its types say cannot occur.
      '@typescript-eslint/no-unnecessary-condition': 'off',
      // Scene objects are narrowed by their type tag rather than instanceof on the per-frame path.
      '@typescript-eslint/no-unsafe-class-instance-assignment': 'off',
      // Short arrows that return a void call (`() => gl.deleteBuffer(b)`) are the code's style.
      '@typescript-eslint/no-confusing-void-expression': 'off',
      // Numbers, booleans and nullish values read fine in messages; objects and arrays still do not pass.
      '@typescript-eslint/restrict-template-expressions': [
        'error',
        { allowNumber: true, allowBoolean: true, allowNullish: true },
      ],
    },
  },
  {
    files: ['**/*.{js,mjs,cjs}'],
    languageOptions: { globals: { ...globals.node } },
  },
);
