/**
 * Students of the flood test, in a process of their own (as laptops are not
 * the test runner): `node tests/e2e/flood-students.js URL STUDENTS ANSWERS
 * PIXELS_JSON`. Each student sends an answer about every 0.9 s, as a page
 * does (JSON to /class/send), and its fifth one twice (a page that never heard
 * back sends again). Prints one JSON line: every request's status, time on
 * the wire (ms) and time in the server (Server-Timing), and the seconds it took.
 */
const [url, students, answers, pixelsJSON] = process.argv.slice(2);
const pixels = JSON.parse(pixelsJSON);
const SCREEN = { width: 32, height: 24, fov: 30 };
const results = [];

async function send(body) {
  const t0 = performance.now();
  const answer = await fetch(`${url}class/send`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
  const reply = await answer.json();
  const server = Number(/dur=([\d.]+)/.exec(answer.headers.get('server-timing') ?? '')?.[1] ?? NaN);
  results.push({ status: answer.status, ms: performance.now() - t0, server, again: reply.again, at: Date.now() });
}

const t0 = performance.now();
await Promise.all(Array.from({ length: Number(students) }, async (_, s) => {
  const laptop = `flood-laptop-${String(s).padStart(2, '0')}`;
  for (let i = 0; i < Number(answers); i++) {
    const at = i * 900 + Math.random() * 300; // the class out of step
    await new Promise((r) => setTimeout(r, Math.max(0, t0 + at - performance.now())));
    const p = pixels[(s * Number(answers) + i) % pixels.length];
    const body = { laptop, nickname: `S${s}`, id: `f${i}`, kind: 'answer', line: `Pixel: ${p.x},${p.y}; H: 0; V: 0`, ...SCREEN };
    await send(body);
    if (i === 4) await send(body);
  }
}));
console.log(JSON.stringify({ seconds: (performance.now() - t0) / 1000, results }));
