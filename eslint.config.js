// ESLint (flat config): the recommended rules, and nothing unused left behind.
import js from '@eslint/js';
import globals from 'globals';
import stylistic from '@stylistic/eslint-plugin';

export default [
  { ignores: ['dist/**', 'dist-teacher/**', 'bench/live/**', 'types/**', 'node_modules/**', 'test-results/**', 'playwright-report/**', 'tests/e2e/pages/live-*'] },
  js.configs.recommended,
  {
    languageOptions: {
      ecmaVersion: 2024,
      sourceType: 'module',
      globals: { ...globals.browser, ...globals.node, ...globals.worker },
    },
    rules: {
      // Arguments are kept when a callback's or an API's shape asks for them.
      'no-unused-vars': ['error', { args: 'none', caughtErrors: 'none' }],
    },
  },
  {
    // The format check: the house style, as the code is written (no reformatting tool).
    plugins: { '@stylistic': stylistic },
    rules: {
      '@stylistic/indent': ['error', 2, { SwitchCase: 1, ignoredNodes: ['TemplateLiteral *', 'ConditionalExpression'] }],
      '@stylistic/semi': ['error', 'always'],
      '@stylistic/quotes': ['error', 'single', { avoidEscape: true, allowTemplateLiterals: 'always' }],
      '@stylistic/comma-dangle': ['error', 'always-multiline'],
      '@stylistic/no-trailing-spaces': 'error',
      '@stylistic/eol-last': 'error',
      '@stylistic/no-tabs': 'error',
      '@stylistic/brace-style': ['error', '1tbs', { allowSingleLine: true }],
      '@stylistic/keyword-spacing': 'error',
      '@stylistic/space-infix-ops': 'error',
      '@stylistic/arrow-parens': ['error', 'always'],
    },
  },
  {
    // A homework starter imports what the student's lights will need, before they write them.
    files: ['sketches/*-homework-*.js'],
    rules: { 'no-unused-vars': ['error', { args: 'none', varsIgnorePattern: '^(Sphere|PointLight)$' }] },
  },
  {
    // A global-mode sketch, as the p5 web editor runs it: p5 calls setup() and draw(), p5's
    // functions and the kit's are globals, and RT is the one-file build's library.
    files: ['examples/web-editor/*.js'],
    languageOptions: {
      sourceType: 'script',
      globals: Object.fromEntries([
        'RT', 'createCanvas', 'noCanvas', 'pixelDensity', 'background', 'deltaTime', 'createDiv', 'createSpan', 'createButton', // p5's
        'createTracerView', 'createInspector', 'createSceneView', 'createAnimation', 'createHomeworkCheck', 'drawSideView', 'drawParabola', // the kit's
      ].map((name) => [name, 'readonly'])),
    },
    rules: { 'no-unused-vars': ['error', { args: 'none', varsIgnorePattern: '^(setup|draw)$' }] },
  },
  {
    // The browser test of the one-file build runs code in the page, where RT is a global.
    files: ['tests/e2e/web-editor.spec.js', 'tests/e2e/web-editor-starters.spec.js'],
    languageOptions: { globals: { RT: 'readonly', p5: 'readonly' } },
  },
];
