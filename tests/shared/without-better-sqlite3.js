/**
 * A machine where better-sqlite3 could not be built: `node --import
 * ./tests/shared/without-better-sqlite3.js …` (or in NODE_OPTIONS, for the
 * processes it starts) finds no such package, by import or by require, as
 * after an `npm ci` that could not compile it (npm then leaves an optional
 * dependency out without a word).
 */
import Module, { register } from 'node:module';

const MISSING = "Cannot find package 'better-sqlite3' (not built on this machine)";
// By its name, or by its path (a bundled config file names it by where it is).
const isIt = (specifier) => /(^|[\\/])better-sqlite3([\\/]|$)/.test(specifier);

const hook = `export async function resolve(specifier, context, next) {
  if ((${isIt})(specifier)) throw Object.assign(new Error(${JSON.stringify(MISSING)}), { code: 'ERR_MODULE_NOT_FOUND' });
  return next(specifier, context);
}`;
register(`data:text/javascript,${encodeURIComponent(hook)}`);

// require() (a bundled config file may require it) does not ask the hooks above on this Node.
const resolveFilename = Module._resolveFilename;
Module._resolveFilename = function (request, ...rest) {
  if (isIt(request)) throw Object.assign(new Error(MISSING), { code: 'MODULE_NOT_FOUND' });
  return resolveFilename.call(this, request, ...rest);
};
