// A link longer than Node reads (16 kB of request line and headers) gets a page
// saying so (scripts/long-links.js), not the bare 431 a browser shows as blank.
import { describe, it, expect, beforeAll, afterAll } from 'vitest';
import { createServer } from 'node:http';
import { connect } from 'node:net';
import { answerLongLinks } from '../../scripts/long-links.js';

let server, port;
beforeAll(async () => {
  server = createServer((req, res) => res.end('ok'));
  // As Vite's own listener does: a bare answer, unless the socket was answered already.
  server.on('clientError', (error, socket) => { if (socket.writable) socket.end(`HTTP/1.1 ${error.code === 'HPE_HEADER_OVERFLOW' ? '431 Request Header Fields Too Large' : '400 Bad Request'}\r\nConnection: close\r\n\r\n`); });
  answerLongLinks(server);
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  port = server.address().port;
});
afterAll(() => new Promise((resolve) => server.close(resolve)));

/** Sends `request` as it is; resolves with the whole answer as text. */
function send(request) {
  return new Promise((resolve, reject) => {
    const socket = connect(port, '127.0.0.1', () => socket.end(request));
    let answer = '';
    socket.on('data', (chunk) => { answer += chunk; });
    socket.on('end', () => resolve(answer));
    socket.on('error', reject);
  });
}

describe('answerLongLinks', () => {
  it('a 20 kB link gets 431 and a page that says the link is too long', async () => {
    const answer = await send(`GET /sketches/05-value-boxes.html?scene=${'A'.repeat(20_000)} HTTP/1.1\r\nHost: x\r\n\r\n`);
    expect(answer).toMatch(/^HTTP\/1\.1 431 /);
    expect(answer).toContain('Content-Type: text/html; charset=utf-8');
    expect(answer).toContain('<h1>This link is too long</h1>');
    expect(answer).toContain('#scene=');
  });

  it('a short link is served, a malformed request gets the other listener\'s 400', async () => {
    expect(await send('GET /?scene=abc HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n')).toMatch(/^HTTP\/1\.1 200 [^]*ok$/);
    expect(await send('NOT HTTP AT ALL\r\n\r\n')).toMatch(/^HTTP\/1\.1 400 Bad Request/);
  });
});
