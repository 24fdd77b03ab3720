import { defineConfig } from 'vitest/config';

// Only the unit tests: Playwright's *.spec.js files under tests/e2e are not Vitest's.
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.js'],
    environment: 'node',
    // Picture and property tests trace whole frames: room for a loaded 2-core machine.
    testTimeout: 30_000,
  },
});
