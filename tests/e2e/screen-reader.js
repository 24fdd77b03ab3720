// A screen reader, modelled on NVDA's defaults, for walks through a page by
// keys alone: what it says comes from the browser's accessibility tree (the
// focused node's name, role and description; the live regions' changes; a
// read-all of the page), and the keys it passes to the page depend on its
// mode. In browse mode the arrow keys and letters move its own cursor and
// never reach the page; it switches to focus mode (every key to the page) when
// the focus lands on a widget that needs the keys: a text box, a slider, or
// anything inside an application or a grid. Every key press and every word
// said is counted, to hold a walk to a budget.

/** Roles whose focus puts NVDA in focus mode (its automatic focus mode for focus changes). */
const FOCUS_MODE_ROLES = new Set(['textbox', 'searchbox', 'combobox', 'slider', 'spinbutton', 'listbox', 'menu', 'tree', 'grid', 'treegrid', 'application']);
/** Keys that stay with the screen reader in browse mode (its cursor, its quick navigation). */
const browseKey = (key) => /^(Arrow(Up|Down|Left|Right)|Home|End|PageUp|PageDown|Shift\+Arrow.*|[a-z]|Shift\+[a-z])$/i.test(key);
/** Roles read as their name and role word, their inside not read again. */
const LEAF_ROLES = new Set(['button', 'textbox', 'checkbox', 'radio', 'combobox', 'slider', 'img', 'image', 'application', 'progressbar', 'spinbutton', 'switch', 'searchbox']);
/** How a role is said (Chromium's role names to NVDA's words). */
const ROLE_WORDS = { img: 'graphic', image: 'graphic', textbox: 'edit', button: 'button', link: 'link', checkbox: 'check box',
  heading: 'heading', application: 'application', slider: 'slider', progressbar: 'progress bar', combobox: 'combo box',
  main: 'main landmark' };

export const countWords = (text) => String(text).split(/\s+/).filter((w) => /[\p{L}\p{N}]/u.test(w)).length;

export class ScreenReader {
  /** Keys pressed in the walk. */
  keys = 0;
  /** What was said, in order: `{ how: 'focus' | 'live' | 'read', text }`. */
  said = [];
  mode = 'browse';
  #page; #cdp; #focusPath = [];

  /** @param {import('@playwright/test').Page} page a page already loaded */
  static async start(page) {
    const reader = new ScreenReader();
    reader.#page = page;
    reader.#cdp = await page.context().newCDPSession(page);
    await reader.#cdp.send('Accessibility.enable');
    await page.evaluate(() => {
      window.__said = [];
      const live = '[aria-live]:not([aria-live="off"]), [role="status"], [role="alert"], [role="log"]';
      new MutationObserver((records) => {
        const regions = new Set(records.map((r) => (r.target.nodeType === 1 ? r.target : r.target.parentElement)?.closest(live)).filter(Boolean));
        for (const region of regions) if (region.textContent.trim()) window.__said.push(region.textContent.trim());
      }).observe(document.body, { subtree: true, childList: true, characterData: true });
    });
    return reader;
  }

  /** Every word said so far. */
  get words() { return this.said.reduce((n, s) => n + countWords(s.text), 0); }
  /** What was said, as one text. */
  get text() { return this.said.map((s) => s.text).join(' | '); }

  /**
   * Presses a key as the student would, with the screen reader in between: in
   * browse mode a cursor key stays with it (nothing reaches the page).
   * @param {string} key Playwright's key name ('Tab', 'Shift+Tab', 'Enter', 'p', 'ArrowRight')
   * @param {number} [times=1]
   */
  async press(key, times = 1) {
    for (let i = 0; i < times; i++) {
      this.keys++;
      if (this.mode === 'browse' && browseKey(key)) continue; // the virtual cursor moves; the page hears nothing
      await this.#page.keyboard.press(key);
      await this.#listen();
    }
  }

  /** Types text into the focused box, a key a character (focus mode only: in browse mode the letters stay with the reader). */
  async type(text) {
    for (const ch of text) await this.press(ch === ' ' ? 'Space' : ch);
  }

  /** NVDA+Space: switches between browse and focus mode by hand (one key). */
  toggleMode() {
    this.keys++;
    this.mode = this.mode === 'browse' ? 'focus' : 'browse';
  }

  /**
   * Waits for the page's debounced news, then hears what changed: the live regions, the focus.
   * A message still waiting to be said then (a busy machine runs the page's timers late) is
   * waited for: the reader hears it whenever it comes, and it belongs to this key.
   */
  async #listen(ms = 450) {
    await this.#page.waitForTimeout(ms);
    await this.#page.waitForFunction(() => !document.querySelector('[data-announce="page"][data-pending]'), null, { timeout: 10_000 });
    const live = await this.#page.evaluate(() => window.__said.splice(0));
    const { nodes } = await this.#cdp.send('Accessibility.getFullAXTree');
    const byId = new Map(nodes.map((n) => [n.nodeId, n]));
    // the document has the focus too: the deepest focused node is the one
    const focused = nodes.filter((n) => n.properties?.some((p) => p.name === 'focused' && p.value.value)).at(-1);
    const path = [];
    for (let n = focused; n; n = byId.get(n.parentId)) if (!n.ignored) path.unshift(n);
    const entered = path.filter((n) => !this.#focusPath.some((o) => o.backendDOMNodeId === n.backendDOMNodeId && o.backendDOMNodeId !== undefined));
    if (focused && focused.backendDOMNodeId !== this.#focusPath.at(-1)?.backendDOMNodeId) {
      // NVDA says the containers it enters that have a name (an application, a group, a landmark), then the focused node
      const words = entered.filter((n) => n !== focused && name(n) && ['application', 'group', 'region', 'navigation', 'main', 'form', 'dialog'].includes(role(n)))
        .map((n) => `${name(n)} ${roleWord(n)}`);
      words.push(`${name(focused)} ${roleWord(focused)} ${focused.description?.value ?? ''}`.trim());
      this.said.push({ how: 'focus', text: words.join(' ') });
      this.mode = path.some((n) => FOCUS_MODE_ROLES.has(role(n))) ? 'focus' : 'browse';
    }
    this.#focusPath = path;
    for (const text of live) this.said.push({ how: 'live', text });
  }

  /**
   * A read-all (NVDA+Down) from the top of the page: its text as the browse-mode
   * buffer shows it, each control by its name and role; returns the words said.
   */
  async readAll() {
    const { nodes } = await this.#cdp.send('Accessibility.getFullAXTree');
    const byId = new Map(nodes.map((n) => [n.nodeId, n]));
    const out = [];
    const visit = (n) => {
      if (!n) return;
      if (!n.ignored) {
        const r = role(n);
        if (r === 'StaticText' || r === 'text') { out.push(name(n)); return; }
        if (LEAF_ROLES.has(r)) { out.push(`${name(n)} ${roleWord(n)}`); return; }
        if (r === 'link' || r === 'heading') out.push(roleWord(n));
      }
      for (const id of n.childIds ?? []) visit(byId.get(id));
    };
    visit(nodes[0]);
    const text = out.join(' ');
    this.said.push({ how: 'read', text });
    return countWords(text);
  }
}

const role = (n) => n.role?.value ?? '';
const name = (n) => n.name?.value ?? '';
function roleWord(n) {
  const described = n.properties?.find((p) => p.name === 'roledescription')?.value.value;
  return described ?? ROLE_WORDS[role(n)] ?? '';
}
