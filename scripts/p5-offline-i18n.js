/**
 * A Vite (and Rolldown) plugin: p5's friendly-error translations come from
 * node_modules, not from a CDN, and p5's language detection costs the same
 * whatever the length of the page's link.
 *
 * p5 2.x's core/internationalization.js fetches every language but English
 * from cdn.jsdelivr.net (a request outside the page's origin, and a console
 * error on a classroom network without internet), and its language detector
 * ('subdomain') runs a super-linear regex over location.href: a 130 kB share
 * link took 10 s to open. This plugin rewrites that one module as it is
 * bundled: every translation in node_modules/p5/translations is bundled
 * (about 40 kB), the fetching backend is not installed, and the language is
 * read from ?lng=, the browser's languages and <html lang> only.
 *
 * Each rewrite must find its text exactly once: a p5 upgrade that changes the
 * module fails the build loudly rather than bringing the CDN back.
 */
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { join } from 'node:path';

const MODULE = /[\\/]p5[\\/]dist[\\/]core[\\/]internationalization\.js$/;

/** `{ es: { translation: {…} }, … }`: every language p5 ships but English (already bundled by p5). */
function bundledTranslations(root = 'node_modules/p5/translations') {
  const resources = {};
  for (const lng of readdirSync(root)) {
    const file = join(root, lng, 'translation.json');
    if (lng !== 'en' && existsSync(file)) resources[lng] = { translation: JSON.parse(readFileSync(file, 'utf8')) };
  }
  return resources;
}

/** [what p5 says, what we want]: each found exactly once. */
const REWRITES = (translations) => [
  // No backend: nothing is fetched; every language is a bundled resource.
  ['.use(FetchResources)', ''],
  ['resources: fallbackResources', `resources: { ...${JSON.stringify(translations)}, ...fallbackResources }`],
  // Linear detectors only: 'path' and 'subdomain' scan the URL with regexes (and are no language of ours).
  ["order: ['querystring', 'navigator', 'htmlTag', 'path', 'subdomain']", "order: ['querystring', 'navigator', 'htmlTag']"],
];

/** Rewrites p5's internationalization module's source text; throws when p5's text has changed. */
export function rewriteP5Internationalization(code, translations = bundledTranslations()) {
  for (const [from, to] of REWRITES(translations)) {
    const at = code.indexOf(from);
    if (at < 0 || code.indexOf(from, at + 1) >= 0) {
      throw new Error(`p5-offline-i18n: expected "${from}" once in p5's core/internationalization.js; p5 has changed, update scripts/p5-offline-i18n.js`);
    }
    code = code.slice(0, at) + to + code.slice(at + from.length);
  }
  return code;
}

export function p5OfflineI18n() {
  return {
    name: 'p5-offline-i18n',
    transform(code, id) {
      if (!MODULE.test(id.split('?')[0])) return null;
      return { code: rewriteP5Internationalization(code), map: null };
    },
  };
}
