/**
 * A link too long for the server gets a page that says so, not a blank one.
 * Node refuses a request whose line and headers pass its maxHeaderSize
 * (16 kB) before Vite sees it, and answers a bare "431 Request Header Fields
 * Too Large" the browser shows as an empty page: an older share link
 * (`?scene=…`, a scene of 110 spheres is 15 kB of it) did that. The dev
 * server, the class server (`npm run class`) and `vite preview` answer with
 * TOO_LONG_PAGE instead; other malformed requests keep Node's 400.
 */

/** What the browser shows for a link over the server's limit. */
export const TOO_LONG_PAGE = `<!doctype html>
<html lang="en">
<head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1"><title>This link is too long</title></head>
<body style="font: 1.1rem/1.5 system-ui, sans-serif; max-width: 40rem; margin: 3rem auto; padding: 0 1rem">
  <h1>This link is too long</h1>
  <p data-link-too-long>The link is longer than this server reads (16 kB), so the page could not open.
  An older share link holds its scene after <code>?scene=</code>, which is sent to the server;
  a share link made now keeps it after <code>#scene=</code>, which is not, and is shorter.</p>
  <p>Ask whoever sent it to copy the link again from sketch 05 (“Copy link”), or to copy the scene as code.</p>
  <p><a href="/">To the gallery</a></p>
</body>
</html>
`;

/**
 * Answers requests Node finds too long with TOO_LONG_PAGE (431). Put before
 * any other listener (Vite's answers a bare 431, but not on a socket already
 * answered); with none, any other malformed request gets Node's bare 400.
 * @param {import('node:http').Server} server
 */
export function answerLongLinks(server) {
  server.prependListener('clientError', (error, socket) => {
    if (!socket.writable) return;
    if (error.code === 'HPE_HEADER_OVERFLOW') {
      const body = Buffer.from(TOO_LONG_PAGE);
      socket.end(`HTTP/1.1 431 Request Header Fields Too Large\r\nContent-Type: text/html; charset=utf-8\r\nContent-Length: ${body.length}\r\nConnection: close\r\n\r\n${TOO_LONG_PAGE}`);
    } else if (server.listenerCount('clientError') === 1) {
      socket.end('HTTP/1.1 400 Bad Request\r\nConnection: close\r\n\r\n');
    }
  });
}

/** The Vite plugin: the dev and class servers, and `vite preview`. */
export function longLinks() {
  return {
    name: 'long-links',
    configureServer(server) { if (server.httpServer) answerLongLinks(/** @type {any} */ (server.httpServer)); },
    configurePreviewServer(server) { if (server.httpServer) answerLongLinks(/** @type {any} */ (server.httpServer)); },
  };
}
