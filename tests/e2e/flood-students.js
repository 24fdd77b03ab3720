/**
 * Students of the flood test, in a process of their own (as laptops are not
 * the test runner): `node tests/e2e/flood-students.js URL STUDENTS ANSWERS
 * PIXELS_JSON`. Each student says hello (its laptop's secret comes back) and
 * sends an answer about every 0.9 s, as a page does (JSON to /class/send,
 * with the secret), and its fifth one twice (a page that never heard
 * back sends again). Prints one JSON line: every request's status, time on
 * the wire (ms) and time in the server (Server-Timing), and the seconds it took.
 */
const [url, students, answers, pixelsJSON] = process.argv.slice(2);
const pixels = JSON.parse(pixelsJSON);
const SCREEN = { width: 32, height: 24, fov: 30 };
const results = [];

/** Says hello as a new laptop named `nickname`: its id and secret. */
async function hello(base, laptop, nickname) {
  const answer = await fetch(`${base}class/hello`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify({ laptop, nickname }) });
  const body = await answer.json();
  if (!answer.ok) throw new Error(`hello as ${nickname}: ${answer.status} ${body.error}`);
  return body;
}

async function send(body, secret) {
  const t0 = performance.now();
  const answer = await fetch(`${url}class/send`, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-RT-Laptop-Secret': secret }, body: JSON.stringify(body) });
  const reply = await answer.json();
  const server = Number(/dur=([\d.]+)/.exec(answer.headers.get('server-timing') ?? '')?.[1] ?? NaN);
  results.push({ status: answer.status, ms: performance.now() - t0, server, again: reply.again, at: Date.now() });
}

const t0 = performance.now();
await Promise.all(Array.from({ length: Number(students) }, async (_, s) => {
  const { laptop, secret } = await hello(url, `flood-laptop-${String(s).padStart(2, '0')}-${Date.now()}`, `S${s}-${Date.now().toString(36)}`);
  for (let i = 0; i < Number(answers); i++) {
    const at = i * 900 + Math.random() * 300; // the class out of step
    await new Promise((r) => setTimeout(r, Math.max(0, t0 + at - performance.now())));
    const p = pixels[(s * Number(answers) + i) % pixels.length];
    const body = { laptop, id: `f${i}`, kind: 'answer', line: `Pixel: ${p.x},${p.y}; H: 0; V: 0`, ...SCREEN };
    await send(body, secret);
    if (i === 4) await send(body, secret);
  }
}));
console.log(JSON.stringify({ seconds: (performance.now() - t0) / 1000, results }));
