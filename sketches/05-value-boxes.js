/**
 * 05 · Value boxes (the class's example page with input boxes: "Modify the
 * values in the boxes").
 *
 * The scene is just numbers: each sphere's centre (x, y, z) and radius, its
 * colour, how much it reflects and lets through, and its emission — a sphere
 * that gives off light IS a light. Change a box and the picture is traced
 * again; a bad value gets a message beside its box and changes nothing.
 * The scene travels in the page's link (#scene=…, compressed) and as code.
 */
import p5 from 'p5';
import { Camera, classScene, sceneToJSON, sceneCodeLines, joinInSlices, nextTask } from '../lib/index.js';
import { readSceneLink, sceneLinkURL, linkNotice, element, copyText, showInBox } from '../lib/p5/index.js'; // and the p5 addon: p.createTracerView, …

// The picture: its size in pixels and how wide the eye sees.
const WIDTH = 160;
const HEIGHT = 120;
const FOV = 30;

new p5((p) => {
  let view, status;

  p.setup = async () => {
    p.noCanvas();
    const { scene, problem } = await sceneFromLink();
    // The picture, then the boxes, each in a task of its own: at 10,000 spheres each part is checked and built in about 50 ms.
    await nextTask();
    view = p.createTracerView({ scene, camera: new Camera({ width: WIDTH, height: HEIGHT, fov: FOV }), scale: 3, label: `${WIDTH} × ${HEIGHT} pixels` });
    p.createInspector({ view }); // beside the picture

    const values = document.getElementById('values');
    values.parentElement.append(values); // under both: the boxes get the page's whole width
    values.parentElement.before(element('p', { class: 'notice', 'data-link-problem': '', role: 'alert' }, problem));
    const panel = element('section', { class: 'card' }, element('h2', {}, 'The values'));
    values.append(panel, shareTools());
    await nextTask();
    p.createSceneForm({ json: sceneToJSON(scene), parent: panel, onChange: (changed, json) => {
      view.setScene(changed);
      shareInLink(json); // the link now shares this scene
    } });
    p.createTaskList({ page: '05', view }); // the page's tasks, ticked off as they are done
  };

  // #scene=… (or an older ?scene=…) in the link, else the class scene; a bad link says why and shows the class scene.
  async function sceneFromLink() {
    try {
      return { scene: (await readSceneLink(location.href)) ?? classScene(), problem: '' };
    } catch (error) {
      return { scene: classScene(), problem: `The scene in this link could not be read (${error.message}), so here is the class scene.` };
    }
  }

  function shareTools() {
    const codeBox = element('textarea', { rows: '12', readonly: '', spellcheck: 'false', 'data-scene-code': '', 'aria-label': 'The scene as code', hidden: '' });
    status = element('span', { class: 'status', role: 'status' });
    const codeNote = element('p', { class: 'rt-note', 'data-scene-code-note': '' });
    const copyCode = button('Copy scene as code', async () => {
      const code = await joinInSlices(sceneCodeLines(view.scene)); // in slices: 10,000 spheres are 1.4 MB of code
      codeNote.textContent = showInBox(codeBox, code); // a box shows 20,000 characters at most; the copy has them all
      codeBox.hidden = false;
      share(code, 'Code copied: paste it into a sketch.');
    });
    const copyLink = button('Copy link', async () => {
      await linked; // the last edit's link
      const { open, message } = linkNotice(location.href.length);
      if (open) share(location.href, message);
      else status.textContent = message;
    });
    return element('section', { class: 'card share' }, copyCode, copyLink, status, codeBox, codeNote);
  }

  // The link is made in a task of its own, not in the edit's (at 1,000 spheres it takes a few ms),
  // and only for the latest edit: quick edits in a row make one link.
  let edits = 0, linked = Promise.resolve();
  function shareInLink(json) {
    const edit = ++edits;
    linked = (async () => {
      await new Promise((resolve) => setTimeout(resolve));
      if (edit !== edits) return;
      const url = await sceneLinkURL(location.href, json); // compressing is asynchronous too
      if (edit === edits) history.replaceState(null, '', url);
    })();
  }

  const button = (label, onClick) => {
    const b = element('button', { type: 'button', class: 'rt-button' }, label);
    b.addEventListener('click', onClick);
    return b;
  };

  async function share(text, done) {
    status.textContent = (await copyText(text)) ? done : 'Select the text and press Ctrl+C (⌘C).';
  }
}, document.getElementById('sketch'));
