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
 * Then the class board: one answer at a time, the time from its send to the
 * board's live stream showing it; and 30 students sending ten answers each
 * within ten seconds (tests/e2e/flood-students.js, a process of its own):
 * each request's time on the wire and in the server, and how long after the
 * last reply the board had every answer.
 *
 * The exit code is 1 when a request failed, a student's first visit is
 * over 2 MB, or an answer of the flood was not stored once; times are
 * printed, never asserted (the machine is shared).
 *
 * Options: --page sketches/NN-….html (default sketch 06), --students N
 * (default 30), --port N.
 */
import http from 'node:http';
import { spawn } from 'node:child_process';
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
    // The files it reads: not what it sends (its hello to the class board, a POST).
    cdp.on('Network.requestWillBeSent', (e) => { if (/^https?:/.test(e.request.url) && e.request.method === 'GET') urls.set(e.requestId, e.request.url); });
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

/** The board's live stream: `until(test)` resolves with the time (performance.now()) of the first state that passes. */
async function boardStream(url) {
  const stream = await fetch(url);
  const reader = stream.body.getReader();
  const decoder = new TextDecoder();
  let text = '';
  let waiting = null;
  let latest = null;
  (async () => {
    for (;;) {
      const { value, done } = await reader.read().catch(() => ({ done: true }));
      if (done) return;
      text += decoder.decode(value, { stream: true });
      let end;
      while ((end = text.indexOf('\n\n')) >= 0) {
        const data = /^data: (.*)$/m.exec(text.slice(0, end))?.[1];
        text = text.slice(end + 2);
        if (!data) continue;
        latest = JSON.parse(data);
        if (waiting?.test(latest)) { waiting.done(performance.now()); waiting = null; }
      }
    }
  })();
  return {
    until: (test) => new Promise((done) => { if (latest && test(latest)) done(performance.now()); else waiting = { test, done }; }),
    close: () => reader.cancel(),
  };
}

const median = (list) => [...list].sort((a, b) => a - b)[list.length >> 1];
const slowest = (list) => Math.max(...list);
const ms = (n) => `${n.toFixed(0)} ms`;

/** The class board: single answers to the board, then the flood. Returns whether all went as it should. */
async function classBoard(base, output) {
  let key;
  for (let i = 0; i < 100 && !key; i++) {
    key = /\/board\?key=([\w-]+)/.exec(output())?.[1];
    if (!key) await new Promise((r) => setTimeout(r, 100));
  }
  if (!key) { console.log(`\nthe class board is off:${output().split('the class board is off')[1]?.split('\n')[0] ?? ' no address printed'}`); return false; }
  const board = await boardStream(`${base}board/events?key=${key}`);
  const SCREEN = { width: 32, height: 24, fov: 30 };
  // A laptop says hello first: its secret comes back, and every send proves it.
  const hello = await (await fetch(`${base}class/hello`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify({ laptop: `bench-one-${Date.now()}` }) })).json();
  const answer = (id, x, y) => ({ laptop: hello.laptop, id, kind: 'answer', line: `Pixel: ${x},${y}; H: 0; V: 0`, ...SCREEN });
  const post = (body) => fetch(`${base}class/send`, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-RT-Laptop-Secret': hello.secret }, body: JSON.stringify(body) });
  try {
    const single = [];
    for (let i = 0; i < 7; i++) {
      const t0 = performance.now();
      const sent = await post(answer(`one${i}`, i, 3));
      if (sent.status !== 200) { console.log(`\na single answer: ${sent.status}`); return false; }
      const shown = await board.until((state) => state.answers.some((a) => a.line === `Pixel: ${i},3; H: 0; V: 0`));
      single.push(shown - t0);
    }
    console.log(`\nthe class board, one answer at a time: on the board ${ms(median(single))} after its send (median of ${single.length}, slowest ${ms(slowest(single))}; the board pushes a burst once, within 250 ms)`);

    const pixels = Array.from({ length: 32 * 24 }, (_, i) => ({ x: i % 32, y: Math.floor(i / 32) }));
    const before = (await (await fetch(`${base}board/state?key=${key}`)).json()).answers.length;
    const students = spawn(process.execPath, ['tests/e2e/flood-students.js', base, '30', '10', JSON.stringify(pixels)], { stdio: ['ignore', 'pipe', 'inherit'] });
    let out = '';
    students.stdout.on('data', (d) => { out += d; });
    const all = board.until((state) => state.answers.length >= before + 300);
    await new Promise((done) => students.on('exit', done));
    const { seconds, results } = JSON.parse(out);
    const current = await all;
    const afterLastReply = performance.timeOrigin + current - Math.max(...results.map((r) => r.at)); // both in ms since the epoch
    const stored = (await (await fetch(`${base}board/state?key=${key}`)).json()).answers.length - before;
    const failed = results.filter((r) => r.status !== 200);
    console.log('30 students, ten answers each within ten seconds (the fifth sent twice):');
    console.log(`  ${results.length} requests in ${seconds.toFixed(1)} s, ${failed.length} not 200, ${stored} answers stored (300 expected)`);
    console.log(`  on the wire: median ${ms(median(results.map((r) => r.ms)))}, slowest ${ms(slowest(results.map((r) => r.ms)))}; in the server: median ${ms(median(results.map((r) => r.server)))}, slowest ${ms(slowest(results.map((r) => r.server)))}`);
    console.log(`  the board had every answer ${ms(Math.max(0, afterLastReply))} after the last reply`);
    return failed.length === 0 && stored === 300;
  } finally {
    await board.close();
  }
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
  const boardWorks = await classBoard(server.url, server.output);
  broken = cold.failed.length > 0 || again.failed.length > 0 || cold.maxBytes > LIMIT || first.bytes > LIMIT || !boardWorks;
  if (broken) console.log(`\nBROKEN: a failed request, a visit over ${MB(LIMIT)}, or the class board did not store every answer once`);
} finally {
  await server.close();
}
process.exit(broken ? 1 : 0);
