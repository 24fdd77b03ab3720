// The build's rewrite of p5's internationalization module: no CDN backend,
// every translation bundled, only linear language detectors; a changed p5
// fails loudly.
import { describe, it, expect } from 'vitest';
import { readFileSync } from 'node:fs';
import { rewriteP5Internationalization } from '../../scripts/p5-offline-i18n.js';

const P5_MODULE = readFileSync('node_modules/p5/dist/core/internationalization.js', 'utf8');

describe('p5-offline-i18n', () => {
  const code = rewriteP5Internationalization(P5_MODULE);

  it("p5's module as shipped fetches from the CDN and scans the URL (what the rewrite is for)", () => {
    expect(P5_MODULE).toContain('cdn.jsdelivr.net');
    expect(P5_MODULE).toContain('.use(FetchResources)');
    expect(P5_MODULE).toContain("'subdomain'");
  });

  it('installs no fetching backend', () => {
    expect(code).not.toContain('.use(FetchResources)');
    expect(code).toContain('.use(LanguageDetector)');
  });

  it('bundles every language p5 translates', () => {
    for (const lng of ['es', 'ja', 'ko', 'zh', 'hi']) {
      const text = JSON.parse(readFileSync(`node_modules/p5/translations/${lng}/translation.json`, 'utf8'));
      expect(code).toContain(`"${lng}":{"translation":`);
      expect(code).toContain(JSON.stringify(text.fes.pre));
    }
  });

  it('detects the language from ?lng=, the browser and <html lang> only', () => {
    expect(code).toContain("order: ['querystring', 'navigator', 'htmlTag']");
    expect(code).not.toMatch(/'path'|'subdomain'/);
  });

  it('fails loudly when p5 has changed', () => {
    expect(() => rewriteP5Internationalization(P5_MODULE.replace('.use(FetchResources)', '.use(OtherBackend)'))).toThrow(/p5 has changed/);
    expect(() => rewriteP5Internationalization(`${P5_MODULE}\n.use(FetchResources)`)).toThrow(/expected/);
  });
});
