/**
 * A class of 30 on one laptop: `npm run bench:class`.
 *
 * Starts `npm run class` (port 5179, or --port N / BENCH_CLASS_PORT), opens a
 * sketch page in headless Chromium once (the first student: which files the
 * page asks for, the bytes on the wire, the time until its picture is done),
 * then 30 students at once on 127.0.0.1: each asks for every one of those
 * files as a browser with an empty cache does (its own keep-alive
 * connections, at most 6, `Accept-Encoding: gzip, deflate, br`), then again
 * as a repeat visit does (If-None-Match / If-Modified-Since; files marked
 * immutable are not asked for again). Prints, per visit: bytes on the wire
 * per student (headers and bodies, as read from the sockets), the time until
 * the last student had every file, failed requests, and 304s.
 *
 * The exit code is 1 when a request failed or a student's first visit is
 * over 2 MB; times are printed, never asserted (the machine is shared).
 *
 * Options: --page sketches/NN-….html (default sketch 06), --students N
 * (default 30), --port N.
 */
import http from 'node:http';
import { chromium } from '@playwright/test';
import { findBrowser, HOW_TO_GET_ONE } from '../scripts/find-browser.js';
import { startClassServer } from '../tests/e2e/class-server.js';

const option = (name) => { const i = process.argv.indexOf(name); return i < 0 ? undefined : process.argv[i + 1]; };
const PORT = Number(option('--port') ?? process.env.BENCH_CLASS_PORT ?? 5179);
const PAGE = option('--page') ?? 'sketches/06-lights-shadows-reflections.html';
const STUDENTS = Number(option('--students') ?? 30);
const LIMIT = 2e6; // bytes on the wire per student for a sketch page
const MB = (n) => `${(n / 1e6).toFixed(2)} MB`;

/** The first student, in Chromium: the URLs the page asks for, bytes on the wire, time to a finished picture. */
async function firstStudent(base) {
  const executablePath = findBrowser();
  if (!executablePath) throw new Error(HOW_TO_GET_ONE);
  const browser = await chromium.launch({ executablePath });
  try {
    const context = await browser.newContext();
    const page = await context.newPage();
    const cdp = await context.newCDPSession(page);
    await cdp.send('Network.enable');
    const urls = new Map();
    let bytes = 0;
    cdp.on('Network.requestWillBeSent', (e) => { if (/^https?:/.test(e.request.url)) urls.set(e.requestId, e.request.url); });
    cdp.on('Network.loadingFinished', (e) => { bytes += e.encodedDataLength; });
    const t0 = performance.now();
    await page.goto(base + PAGE);
    await page.waitForSelector('body[data-render="done"]', { timeout: 120_000 });
    const ms = performance.now() - t0;
    await page.waitForLoadState('networkidle');
    return { urls: [...new Set(urls.values())], bytes, ms };
  } finally {
    await browser.close();
  }
}

/** One GET on `agent`; resolves with its status and headers, counting the socket it used. */
function get(url, agent, sockets, headers) {
  return new Promise((done) => {
    const req = http.get(url, { agent, headers: { 'Accept-Encoding': 'gzip, deflate, br', ...headers } }, (res) => {
      res.on('data', () => {});
      res.on('end', () => done({ url, status: res.statusCode, headers: res.headers }));
      res.on('error', (error) => done({ url, status: 0, error }));
    });
    req.on('socket', (socket) => sockets.add(socket));
    req.on('error', (error) => done({ url, status: 0, error }));
  });
}

/** One student's visit: every URL, 6 connections at most; `before` the answers of a first visit (to revalidate). */
async function visit(urls, before = null) {
  const agent = new http.Agent({ keepAlive: true, maxSockets: 6 });
  const sockets = new Set();
  const asks = urls.flatMap((url) => {
    const old = before?.get(url);
    if (!old?.headers) return [get(url, agent, sockets, {})];
    if (/immutable/.test(old.headers['cache-control'] ?? '')) return []; // the browser does not ask again
    const headers = {};
    if (old.headers.etag) headers['If-None-Match'] = old.headers.etag;
    if (old.headers['last-modified']) headers['If-Modified-Since'] = old.headers['last-modified'];
    return [get(url, agent, sockets, headers)];
  });
  const answers = await Promise.all(asks);
  const bytes = [...sockets].reduce((sum, s) => sum + s.bytesRead, 0);
  agent.destroy();
  return { answers, bytes };
}

/** STUDENTS visits at once; the figures of the lot. */
async function classVisits(urls, befores = null) {
  const t0 = performance.now();
  const visits = await Promise.all(Array.from({ length: STUDENTS }, (_, i) => visit(urls, befores?.[i])));
  const ms = performance.now() - t0;
  const answers = visits.flatMap((v) => v.answers);
  const perStudent = visits.map((v) => v.bytes);
  return {
    visits, ms,
    requests: answers.length,
    failed: answers.filter((a) => a.status === 0 || a.status >= 400),
    notModified: answers.filter((a) => a.status === 304).length,
    maxBytes: Math.max(...perStudent),
    meanBytes: perStudent.reduce((a, b) => a + b, 0) / perStudent.length,
  };
}

function report(title, figures) {
  console.log(`\n${title}`);
  console.log(`  ${figures.requests} requests (${figures.requests / STUDENTS} a student), ${figures.failed.length} failed, ${figures.notModified} answered 304`);
  console.log(`  on the wire a student: ${MB(figures.meanBytes)} (at most ${MB(figures.maxBytes)}); the class: ${MB(figures.meanBytes * STUDENTS)}`);
  console.log(`  the last student had every file after ${(figures.ms / 1000).toFixed(1)} s`);
  for (const f of figures.failed.slice(0, 5)) console.log(`  failed: ${f.status} ${f.url} ${f.error?.message ?? ''}`);
}

const server = await startClassServer(PORT);
let broken;
try {
  console.log(`npm run class on port ${PORT}: ${PAGE}, ${STUDENTS} students at once on 127.0.0.1`);
  const first = await firstStudent(server.url);
  console.log(`\nthe first student (Chromium, empty cache): ${first.urls.length} files, ${MB(first.bytes)} on the wire, picture done after ${(first.ms / 1000).toFixed(1)} s`);
  const cold = await classVisits(first.urls);
  report(`${STUDENTS} students, first visit (empty caches):`, cold);
  const befores = cold.visits.map((v) => new Map(v.answers.map((a) => [a.url, a])));
  const again = await classVisits(first.urls, befores);
  report(`${STUDENTS} students, repeat visit (revalidated):`, again);
  broken = cold.failed.length > 0 || again.failed.length > 0 || cold.maxBytes > LIMIT || first.bytes > LIMIT;
  if (broken) console.log(`\nBROKEN: a failed request, or a visit over ${MB(LIMIT)}`);
} finally {
  await server.close();
}
process.exit(broken ? 1 : 0);
