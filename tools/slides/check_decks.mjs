#!/usr/bin/env node
// The lecture decks' real-browser test: opens every deck of build/slides/manifest.json (written by
// tools/slides/build.py) in headless chromium and checks, per deck:
//   (a) every <img> has loaded (complete, naturalWidth > 0);
//   (b) Reveal.getTotalSlides() is the slide count the Markdown asks for;
//   (c) every figure is byte for byte the PNG the solution rendered for its demo step (the data:
//       URI decoded and hashed, against the manifest and the file), on the slide it was written on;
//   (d) the equations are there: as many <math> elements as the Markdown has math, each laid out;
//   (e) nothing was fetched from the network (every request is intercepted; only file:, data:,
//       blob: and about: may load), and no element refers to http(s);
//   (f) no slide's content is taller or wider than the slide (a cut-off figure or line);
//   and the page raised no JavaScript error and every font loaded.
// It saves screenshots of the title slide and the first two figure slides of every deck to
// SHOTS/NN_name-S.png (S: the slide's number, 1 = title), prints one PASS/FAIL line per deck and
// exits 1 if any deck failed (2 when it cannot run: no chromium, no puppeteer-core, no manifest).
//
//   node tools/slides/check_decks.mjs [build/slides/manifest.json] [--shots DIR] [--labs 02,05]
//        [--chromium PATH] [--timeout SECONDS] [--all-shots]
//   --all-shots: a screenshot of every slide, not only of the title and two figure slides.
//   node tools/slides/check_decks.mjs --print-pdf DECK.html OUT.pdf
//   prints one deck as reveal.js lays it out for print (?print-pdf), one page per slide, once its
//   figures are fitted and its pages laid out (build.py --pdf runs this).
//
// puppeteer-core comes from slides/node_modules (npm ci --prefix slides); it downloads no browser:
// the browser is Debian's chromium (apt-get install chromium), or $CHROMIUM.
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readFileSync, accessSync, constants } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

function usage(message) {
  if (message) console.error(`check_decks: ${message}`);
  console.error('usage: node tools/slides/check_decks.mjs [MANIFEST] [--shots DIR] [--labs 02,05] ' +
    '[--chromium PATH] [--timeout SECONDS] [--all-shots]\n' +
    '       node tools/slides/check_decks.mjs --print-pdf DECK.html OUT.pdf');
  process.exit(2);
}

function parseArgs(argv) {
  const opts = { manifest: path.join('build', 'slides', 'manifest.json'), shots: null, labs: null,
    chromium: process.env.CHROMIUM || null, timeout: 60, allShots: false, printPdf: null };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => (i + 1 < argv.length ? argv[++i] : usage(`${a} needs a value`));
    if (a === '--shots') opts.shots = value();
    else if (a === '--labs') opts.labs = value().split(',').map((s) => s.trim()).filter(Boolean);
    else if (a === '--chromium') opts.chromium = value();
    else if (a === '--all-shots') opts.allShots = true;
    else if (a === '--print-pdf') opts.printPdf = [value(), value()];
    else if (a === '--timeout') opts.timeout = Number(value());
    else if (a === '-h' || a === '--help') usage();
    else if (a.startsWith('-')) usage(`unknown option ${a}`);
    else opts.manifest = a;
  }
  if (!(opts.timeout > 0)) usage('--timeout takes seconds');
  return opts;
}

function findChromium(given) {
  const candidates = given ? [given] : ['/usr/lib/chromium/chromium', '/usr/bin/chromium',
    '/usr/bin/chromium-browser', '/usr/bin/google-chrome'];
  for (const c of candidates) {
    try { accessSync(c, constants.X_OK); return c; } catch { /* next */ }
  }
  console.error(given ? `check_decks: ${given} is not an executable browser`
    : 'check_decks: chromium is not installed: apt-get install -y chromium (or set CHROMIUM=/path/to/chrome)');
  process.exit(2);
}

function loadPuppeteer() {
  const require = createRequire(path.join(ROOT, 'slides', 'package.json'));
  try {
    return require('puppeteer-core');
  } catch {
    console.error('check_decks: puppeteer-core is not installed: npm ci --prefix slides');
    process.exit(2);
  }
}

const sha256 = (buf) => createHash('sha256').update(buf).digest('hex');
const LOCAL = /^(file|data|blob|about|chrome-error):/i;

function decodeDataUri(uri) {
  const m = /^data:([^;,]*)((?:;[^;,]*)*?);base64,(.*)$/s.exec(uri || '');
  if (!m) return null;
  return { type: m[1], bytes: Buffer.from(m[3], 'base64') };
}

// A lecture hall's projector is 1920x1080 as often as 1280x720: every deck is checked at both.
const VIEWPORTS = [[1280, 720], [1920, 1080]];

async function checkDeck(browser, deck, dir, shotsDir, timeoutMs, allShots, viewport = VIEWPORTS[0]) {
  const failures = [];
  const notes = [];
  const fail = (s) => failures.push(s);
  const htmlPath = path.join(dir, deck.html);
  if (!existsSync(htmlPath)) return { failures: [`${htmlPath} does not exist (run tools/slides/build.py)`], notes };

  const page = await browser.newPage();
  try {
    await page.setViewport({ width: viewport[0], height: viewport[1], deviceScaleFactor: 1 });
    const external = new Set();
    const failed = [];
    const errors = [];
    await page.setRequestInterception(true);
    page.on('request', (req) => {
      const url = req.url();
      if (LOCAL.test(url)) {
        req.continue().catch(() => {});
      } else {
        external.add(url);
        req.abort('blockedbyclient').catch(() => {});
      }
    });
    page.on('requestfailed', (req) => {
      if (LOCAL.test(req.url())) failed.push(`${req.url().slice(0, 80)}: ${req.failure()?.errorText}`);
    });
    page.on('pageerror', (err) => errors.push(String(err.message || err).split('\n')[0]));
    page.on('console', (msg) => {
      // a request this test blocked is reported under (e), not as a script error
      if (msg.type() === 'error' && !/ERR_BLOCKED_BY_CLIENT/.test(msg.text())) errors.push(`console: ${msg.text().slice(0, 160)}`);
    });

    await page.goto(pathToFileURL(htmlPath).href, { waitUntil: 'load', timeout: timeoutMs });
    // Wait for reveal.js and the figure fitting (build.py's script), but not for long after a
    // JavaScript error: a deck that throws never gets ready.
    const ready = () => page.evaluate(() => !!(window.Reveal && window.Reveal.isReady && window.Reveal.isReady() &&
      document.documentElement.dataset.figuresFitted === '1'));
    const start = Date.now();
    let ok = false;
    let errorSince = null;
    while (!(ok = await ready()) && Date.now() - start < timeoutMs) {
      if (errors.length && errorSince === null) errorSince = Date.now();
      if (errorSince !== null && Date.now() - errorSince > 3000) break;
      await new Promise((res) => setTimeout(res, 100));
    }
    if (!ok) {
      const state = await page.evaluate(() => ({ reveal: !!window.Reveal,
        ready: !!(window.Reveal && window.Reveal.isReady && window.Reveal.isReady()),
        fitted: document.documentElement.dataset.figuresFitted === '1' }));
      fail(`reveal.js not ready after ${((Date.now() - start) / 1000).toFixed(1)} s (Reveal: ${state.reveal}, ` +
        `ready: ${state.ready}, figures fitted: ${state.fitted})`);
      return { failures: failures.concat(errors.map((e) => `JavaScript error: ${e}`)), notes };
    }
    await page.evaluate(() => window.Reveal.configure({ transition: 'none', backgroundTransition: 'none' }));

    const info = await page.evaluate(() => {
      const R = window.Reveal;
      const slides = R.getSlides();
      const imgs = Array.from(document.querySelectorAll('.reveal .slides img')).map((img) => ({
        src: img.getAttribute('src') || '', complete: img.complete, w: img.naturalWidth, h: img.naturalHeight,
        slide: slides.indexOf(img.closest('section')), alt: img.alt }));
      const refs = [];
      for (const el of document.querySelectorAll('[src], [href], [srcset], [poster], object[data]')) {
        if (el.tagName === 'A') continue;  // a link the lecturer may click is not a fetch
        for (const attr of ['src', 'href', 'srcset', 'poster', 'data']) {
          const v = el.getAttribute(attr);
          if (v && /^\s*(https?:)?\/\//i.test(v)) refs.push(`<${el.tagName.toLowerCase()} ${attr}="${v.slice(0, 80)}">`);
        }
      }
      const resources = performance.getEntriesByType('resource').map((e) => e.name).filter((n) => /^(https?|wss?):/i.test(n));
      const fontErrors = Array.from(document.fonts || []).filter((f) => f.status === 'error').map((f) => f.family);
      return { total: R.getTotalSlides(), count: slides.length, imgs, refs, resources, fontErrors,
        math: document.querySelectorAll('.reveal .slides math').length, config: { w: R.getConfig().width, h: R.getConfig().height } };
    });

    // (a) images loaded
    const broken = info.imgs.filter((i) => !i.complete || !(i.w > 0));
    if (broken.length) fail(`${broken.length} image(s) did not load: ${broken.map((i) => `slide ${i.slide + 1} '${i.alt}'`).join(', ')}`);

    // (b) slide count
    if (info.total !== deck.expected_slides) {
      fail(`Reveal.getTotalSlides() is ${info.total}, the Markdown makes ${deck.expected_slides} (title slide + one per heading)`);
    }

    // (c) figures are the renders
    const figures = deck.figures || [];
    if (info.imgs.length !== figures.length) {
      fail(`the deck has ${info.imgs.length} image(s), the manifest ${figures.length} figure(s)`);
    }
    let matched = 0;
    figures.forEach((fig, n) => {
      const img = info.imgs[n];
      const what = `figure ${n + 1} (step ${fig.step}, line ${fig.line})`;
      let onDisk = null;
      try { onDisk = sha256(readFileSync(path.join(dir, fig.png))); } catch { fail(`${what}: ${fig.png} is missing`); }
      if (onDisk && onDisk !== fig.sha256) fail(`${what}: ${fig.png} changed after the build (sha256 differs from the manifest)`);
      if (!img) return;
      const data = decodeDataUri(img.src);
      if (!data) { fail(`${what}: not inlined as a data: URI (src ${img.src.slice(0, 60)})`); return; }
      if (data.type !== 'image/png') fail(`${what}: inlined as ${data.type}, not image/png`);
      const got = sha256(data.bytes);
      if (got !== fig.sha256) { fail(`${what}: the image in the deck is not the rendered ${fig.png} (sha256 ${got.slice(0, 12)} vs ${fig.sha256.slice(0, 12)})`); return; }
      if (img.slide !== fig.slide) fail(`${what}: on slide ${img.slide + 1}, the Markdown puts it on slide ${fig.slide + 1}`);
      if (img.w !== fig.width || img.h !== fig.height) fail(`${what}: decodes to ${img.w}x${img.h}, rendered ${fig.width}x${fig.height}`);
      matched++;
    });

    // (c') clips: inlined WebM that the browser decodes and plays (currentTime moves)
    const clips = deck.clips || [];
    const videos = await page.evaluate(async () => {
      const R = window.Reveal;
      const out = [];
      for (const v of Array.from(document.querySelectorAll('.reveal .slides video'))) {
        const at = R.getIndices(v.closest('section'));
        R.slide(at.h, at.v);
        v.muted = true;
        let played = '';
        try { await v.play(); } catch (e) { played = String(e); }
        const t0 = v.currentTime;
        await new Promise((res) => setTimeout(res, 1500));
        out.push({ src: (v.getAttribute('src') || '').slice(0, 40), type: (v.getAttribute('src') || '').split(';')[0],
          w: v.videoWidth, h: v.videoHeight, moved: v.currentTime - t0, state: v.readyState, error: v.error ? v.error.code : 0,
          played });
      }
      return out;
    });
    if (videos.length !== clips.length) fail(`the deck has ${videos.length} video(s), the manifest ${clips.length} clip(s)`);
    videos.forEach((v, n) => {
      const what = `clip ${n + 1} (step ${clips[n] ? clips[n].step : '?'})`;
      if (v.type !== 'data:video/webm') fail(`${what}: not inlined as data:video/webm (src ${v.src})`);
      else if (v.error || v.played || !(v.w > 0) || !(v.moved > 0.2)) {
        fail(`${what}: does not play (error ${v.error}, ${v.played || 'play() ok'}, ${v.w}x${v.h}, ` +
          `advanced ${v.moved.toFixed(2)} s in 1.5 s)`);
      } else notes.push(`${what}: plays (${v.w}x${v.h}, ${v.moved.toFixed(2)} s in 1.5 s)`);
    });

    // (d) math
    if ((deck.dollar_lines || 0) > 0 && info.math === 0) fail(`the Markdown has $ on ${deck.dollar_lines} line(s) but the deck has no <math>`);
    else if ((deck.math || 0) > 0 && info.math === 0) fail(`the Markdown has ${deck.math} equation(s) but the deck has no <math>`);
    else if (info.math !== (deck.math || 0)) fail(`${info.math} <math> element(s), the Markdown has ${deck.math} equation(s) (one not converted to MathML?)`);

    // (f) per slide: content fits, figures whole, math laid out
    for (let s = 0; s < info.count; s++) {
      const r = await page.evaluate((s) => {
        const R = window.Reveal;
        const slide = R.getSlides()[s];
        const { h, v } = R.getIndices(slide);
        R.slide(h, v);
        const cfg = R.getConfig();
        const box = R.getSlidesElement().getBoundingClientRect();
        const scale = R.getScale();
        const out = { over: slide.scrollHeight - cfg.height, wide: slide.scrollWidth - cfg.width, cut: [], flatMath: 0, small: [],
          shrunk: slide.getAttribute('data-fit-scale') };
        const inside = (rc) => rc.top >= box.top - 1 && rc.bottom <= box.top + cfg.height * scale + 1 &&
          rc.left >= box.left - 1 && rc.right <= box.left + cfg.width * scale + 1 &&
          rc.top >= -1 && rc.left >= -1 && rc.bottom <= window.innerHeight + 1 && rc.right <= window.innerWidth + 1;
        slide.querySelectorAll('img').forEach((img) => {
          const rc = img.getBoundingClientRect();
          if (!inside(rc)) out.cut.push(img.alt || 'image');
          if (rc.height < 150) out.small.push(`${Math.round(rc.height)} px`);
        });
        slide.querySelectorAll('math').forEach((m) => {
          const rc = m.getBoundingClientRect();
          if (!(rc.width > 0 && rc.height > 0) || !inside(rc)) out.flatMath++;
        });
        return out;
      }, s);
      if (r.over > 1) fail(`slide ${s + 1}: its content is ${r.over} px taller than the slide (cut off)`);
      if (r.wide > 1) fail(`slide ${s + 1}: its content is ${r.wide} px wider than the slide`);
      if (r.cut.length) fail(`slide ${s + 1}: figure '${r.cut[0]}' is not wholly on the slide`);
      if (r.flatMath) fail(`slide ${s + 1}: ${r.flatMath} equation(s) not laid out on the slide (MathML not rendered?)`);
      if (r.shrunk) notes.push(`slide ${s + 1}: text shrunk to ${Math.round(100 * r.shrunk)} % to fit`);
      if (r.small.length) notes.push(`slide ${s + 1}: figure only ${r.small.join(', ')} high (too much else on the slide?)`);
    }

    // the math font build.py inlined (when the deck has math and the build machine had one)
    if (deck.math_font) {
      const states = await page.evaluate(() => Array.from(document.fonts || [])
        .filter((f) => f.family.replace(/["']/g, '') === 'Slides Math').map((f) => f.status));
      if (!states.includes('loaded')) fail(`the inlined math font (${deck.math_font}) did not load (${states.join(', ') || 'not in the page'})`);
    }

    // screenshots: the title slide and the first two figure slides
    if (shotsDir) {
      const wanted = allShots ? [...Array(info.count).keys()]
        : [0, ...(deck.figure_slides || []).filter((s) => s !== 0).slice(0, 2)];
      const saved = [];
      for (const s of wanted) {
        if (s >= info.count) continue;
        await page.evaluate((s) => { const R = window.Reveal; const { h, v } = R.getIndices(R.getSlides()[s]); R.slide(h, v); }, s);
        await page.evaluate(() => new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res))));
        const file = path.join(shotsDir, `${deck.name}-${s + 1}.png`);
        await page.screenshot({ path: file });
        saved.push(file.startsWith(process.cwd() + path.sep) ? path.relative(process.cwd(), file) : file);
      }
      notes.push(`shots: ${saved.join(' ')}`);
    }

    // (e) the network, and the rest
    if (external.size) fail(`${external.size} request(s) to the network: ${[...external].slice(0, 3).join(', ')}`);
    if (info.resources.length) fail(`fetched from the network: ${info.resources.slice(0, 3).join(', ')}`);
    if (info.refs.length) fail(`refers to the network: ${info.refs.slice(0, 3).join(', ')}`);
    if (failed.length) fail(`${failed.length} local load(s) failed: ${failed.slice(0, 2).join('; ')}`);
    if (info.fontErrors.length) fail(`font(s) failed to load: ${[...new Set(info.fontErrors)].join(', ')}`);
    for (const e of errors) fail(`JavaScript error: ${e}`);
    return { failures, notes, summary: `${info.total} slides, ${matched}/${figures.length} figures are their renders, ` +
      `${info.math} equations, ${external.size} network requests` };
  } finally {
    await page.close().catch(() => {});
  }
}

async function launch(opts) {
  const executablePath = findChromium(opts.chromium);
  const puppeteer = loadPuppeteer();
  const args = ['--disable-gpu', '--disable-dev-shm-usage', '--no-first-run', '--no-default-browser-check',
    '--disable-background-networking', '--disable-component-update', '--disable-sync', '--disable-extensions',
    '--allow-file-access-from-files', '--font-render-hinting=none',
    // needed as root, and in containers without user namespaces; the pages are our own local files
    '--no-sandbox'];
  try {
    return await puppeteer.launch({ executablePath, headless: true, args, timeout: opts.timeout * 1000 });
  } catch (e) {
    console.error(`check_decks: could not start ${executablePath}: ${String(e.message || e).split('\n')[0]}`);
    process.exit(2);
  }
}

async function printPdf(opts) {
  const [htmlPath, pdfPath] = opts.printPdf;
  if (!existsSync(htmlPath)) { console.error(`check_decks: ${htmlPath} does not exist`); process.exit(2); }
  const browser = await launch(opts);
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 720, deviceScaleFactor: 1 });
    await page.setRequestInterception(true);
    const external = [];
    page.on('request', (req) => {
      if (LOCAL.test(req.url())) req.continue().catch(() => {});
      else { external.push(req.url()); req.abort('blockedbyclient').catch(() => {}); }
    });
    const errors = [];
    page.on('pageerror', (err) => errors.push(String(err.message || err).split('\n')[0]));
    await page.evaluateOnNewDocument(() => {
      document.addEventListener('pdf-ready', () => { window.__slidesPdfReady = true; }, true);
    });
    await page.goto(pathToFileURL(path.resolve(htmlPath)).href + '?print-pdf', { waitUntil: 'load', timeout: opts.timeout * 1000 });
    try {
      await page.waitForFunction(() => window.__slidesPdfReady === true &&
        document.documentElement.dataset.figuresFitted === '1', { timeout: opts.timeout * 1000, polling: 100 });
    } catch {
      console.error(`check_decks: ${htmlPath}: reveal.js did not lay out its pages for print in ${opts.timeout} s` +
        (errors.length ? ` (JavaScript error: ${errors[0]})` : ''));
      process.exit(1);
    }
    const pages = await page.evaluate(() => ({ pages: document.querySelectorAll('.reveal .pdf-page').length,
      slides: window.Reveal.getTotalSlides() }));
    // pageRanges: chromium adds an empty page after reveal.js's last one.
    await page.pdf({ path: pdfPath, preferCSSPageSize: true, printBackground: true, timeout: opts.timeout * 1000,
      pageRanges: pages.pages > 0 ? `1-${pages.pages}` : '' });
    if (errors.length || external.length) {
      console.error(`check_decks: ${htmlPath}: ${errors.length ? `JavaScript error: ${errors[0]}` : ''}` +
        `${external.length ? ` request(s) to the network: ${external.slice(0, 2).join(', ')}` : ''}`);
      process.exit(1);
    }
    const note = pages.pages === pages.slides ? '' : ` (${pages.slides} slides: a slide longer than a page, or fragments)`;
    console.log(`${pdfPath}: ${pages.pages} pages${note}`);
  } finally {
    await browser.close().catch(() => {});
  }
}

async function main() {
  const opts = parseArgs(process.argv.slice(2));
  if (opts.printPdf) { await printPdf(opts); return; }
  if (!existsSync(opts.manifest)) {
    console.error(`check_decks: ${opts.manifest} does not exist: build the decks first (python3 tools/slides/build.py)`);
    process.exit(2);
  }
  const manifest = JSON.parse(readFileSync(opts.manifest, 'utf8'));
  const dir = path.dirname(path.resolve(opts.manifest));
  let decks = manifest.decks || [];
  if (opts.labs) {
    const missing = opts.labs.filter((l) => !decks.some((d) => d.lab === l));
    if (missing.length) { console.error(`check_decks: no deck for lab ${missing.join(', ')} in ${opts.manifest}`); process.exit(2); }
    decks = decks.filter((d) => opts.labs.includes(d.lab));
  }
  if (!decks.length) { console.error(`check_decks: ${opts.manifest} lists no decks`); process.exit(2); }
  const shotsDir = opts.shots || path.join(dir, 'shots');
  mkdirSync(shotsDir, { recursive: true });

  const browser = await launch(opts);
  const version = await browser.version();
  console.log(`check_decks: ${decks.length} deck(s) from ${opts.manifest} in ${version}`);
  let failedDecks = 0;
  try {
    for (const deck of decks) {
      let failedHere = false;
      for (const viewport of VIEWPORTS) {
        const where = `${deck.name} at ${viewport[0]}x${viewport[1]}`;
        const shots = viewport === VIEWPORTS[0] ? shotsDir : path.join(shotsDir, `${viewport[0]}x${viewport[1]}`);
        mkdirSync(shots, { recursive: true });
        let result;
        try {
          result = await checkDeck(browser, deck, dir, shots, opts.timeout * 1000, opts.allShots, viewport);
        } catch (e) {
          result = { failures: [`the check itself failed: ${String(e.message || e).split('\n')[0]}`], notes: [] };
        }
        if (result.failures.length) {
          failedHere = true;
          console.log(`FAIL ${where}: ${result.failures.join('; ')}`);
        } else {
          console.log(`PASS ${where}: ${result.summary}`);
        }
        for (const n of result.notes) console.log(`     ${where}: ${n}`);
      }
      if (failedHere) failedDecks++;
    }
  } finally {
    await browser.close().catch(() => {});
  }
  console.log(failedDecks ? `check_decks: ${failedDecks} of ${decks.length} deck(s) FAILED`
    : `check_decks: all ${decks.length} deck(s) passed`);
  process.exit(failedDecks ? 1 : 0);
}

main().catch((e) => { console.error(`check_decks: ${e.stack || e}`); process.exit(2); });
