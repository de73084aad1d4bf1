// The page in headless Debian chromium, driven by puppeteer-core (scripts/web-page-test.sh runs
// it against a server of build-web/site):
//   - every page loads with no console error and no uncaught exception;
//   - ?replay=R&speed=max shows the native final `frame N hash H` for every bundled replay;
//   - level 1, driven with keyboard events (paused, one step per N, the golden replay's inputs),
//     reaches PARKED, and the recording downloaded from the page, replayed by the native cardemo,
//     gives the page's frame and hash;
//   - a malformed replay shows the command line's exact `FILE:LINE: ...` in #status, and the
//     picker still starts a level;
//   - free drive's bay chain: a watched drive that parks a bay of the lot, then stands, ends with
//     TIME UP at the native frame and hash of the chain's end;
//   - a screenshot is written and is not blank (pixel variance).
// Usage: node page-test.js URL SITE_DIR NATIVE_CARDEMO OUT_DIR
"use strict";
const { spawnSync } = require("child_process");
const fs = require("fs");
const path = require("path");
const puppeteer = require("puppeteer-core");

const [url, site, native, out] = process.argv.slice(2).map((a, i) => (i === 0 ? a : path.resolve(a)));
const failures = [];
const consoleErrors = [];
let checks = 0;
const started = Date.now();

function check(ok, what) {
  checks += 1;
  if (!ok) failures.push(what);
  console.log(`${ok ? "ok  " : "FAIL"} ${what} [${((Date.now() - started) / 1000).toFixed(1)} s]`);
}

// The native command line's run of a replay, from the site folder (paths as the page names them).
function nativeReplay(args) {
  const run = spawnSync(native, ["replay", ...args, "--json", "-"], { cwd: site, encoding: "utf8" });
  return { status: run.status, stderr: run.stderr.trim(), json: run.status <= 1 ? JSON.parse(run.stdout) : null };
}

// The scene file a replay names, relative to the site.
function sceneOfReplay(replay) {
  const line = fs.readFileSync(path.join(site, replay), "utf8").split("\n").find((l) => l.startsWith("scene "));
  return path.join(path.dirname(replay), line.slice(6).trim());
}

// A copy of `replay` with only its first `frames` frames of input, in OUT_DIR.
function cutReplay(replay, frames) {
  const lines = ["cardemo-replay 1"];
  let left = frames;
  for (const raw of fs.readFileSync(path.join(site, replay), "utf8").split("\n")) {
    const line = raw.replace(/#.*/, "").trim();
    if (line.startsWith("hz ")) lines.push(line);
    const run = /^(\d+) (\S+)$/.exec(line);
    if (!run || left <= 0) continue;
    const count = Math.min(left, Number(run[1]));
    lines.push(`${count} ${run[2]}`);
    left -= count;
  }
  const file = path.join(out, `cut-${path.basename(replay)}`);
  fs.writeFileSync(file, `${lines.join("\n")}\n`);
  return file;
}

async function text(page, id) {
  return page.$eval(`#${id}`, (e) => e.textContent);
}

// Waits until #ID reads `want`; false (and the last text seen) after `ms`.
async function waitText(page, id, want, ms = 60000) {
  try {
    await page.waitForFunction((i, w) => document.getElementById(i).textContent === w, { timeout: ms }, id, want);
    return true;
  } catch (e) {
    console.log(`  #${id} is "${await text(page, id)}", waited for "${want}"`);
    return false;
  }
}

async function open(browser, query) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800 });
  page.on("console", (m) => {
    if (m.type() === "error") consoleErrors.push(`${query}: ${m.text()}`);
  });
  page.on("pageerror", (e) => consoleErrors.push(`${query}: ${e.message}`));
  await page.goto(`${url}/index.html${query}`, { waitUntil: "load" });
  return page;
}

async function frameNumber(page) {
  const m = /^frame (\d+) /.exec(await text(page, "status"));
  return m ? Number(m[1]) : -1;
}

// One fixed step while paused: N, then two of the page's frames (the first runs the step).
async function stepOnce(page) {
  await page.keyboard.press("KeyN");
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

async function replays(browser) {
  const page = await browser.newPage();
  page.on("pageerror", (e) => consoleErrors.push(`replays: ${e.message}`));
  page.on("console", (m) => {
    if (m.type() === "error") consoleErrors.push(`replays: ${m.text()}`);
  });
  for (const name of fs.readdirSync(path.join(site, "assets/replays")).filter((f) => f.endsWith(".replay")).sort()) {
    const replay = `assets/replays/${name}`;
    let want = nativeReplay([replay]).json;
    if (want.parked !== null && want.parked < want.frames) {
      // A level ends once parked: the page, as `cardemo play`, simulates no further. Natively,
      // the same replay cut at that frame.
      want = nativeReplay([cutReplay(replay, want.parked), "--scene", sceneOfReplay(replay)]).json;
    }
    await page.goto(`${url}/index.html?replay=${replay}&speed=max`, { waitUntil: "load" });
    check(await waitText(page, "status", `frame ${want.frames} hash ${want.hash}`), `${replay}&speed=max: native frame ${want.frames} hash ${want.hash}`);
  }
  await page.close();
}

async function levelOne(browser) {
  const page = await open(browser, "");
  check(await waitText(page, "outcome", "picker"), "the picker shows");
  await page.keyboard.press("Enter"); // the first row: level 1
  check(await waitText(page, "outcome", "driving"), "Enter starts level 1");
  await page.keyboard.press("KeyP");
  // level-1-straight.replay's inputs: 283 U, 30 ., 67 D, then nothing until parked.
  const plan = [["ArrowUp", 283], [null, 30], ["ArrowDown", 67]];
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  let stepped = true;
  for (const [key, frames] of plan) {
    const before = await frameNumber(page);
    if (key) await page.keyboard.down(key);
    for (let i = 0; i < frames; ++i) await stepOnce(page);
    if (key) await page.keyboard.up(key);
    stepped = stepped && (await frameNumber(page)) === before + frames;
  }
  check(stepped, "paused, each N runs one step");
  for (let i = 0; i < 400 && (await text(page, "outcome")) !== "PARKED"; ++i) await stepOnce(page);
  check((await text(page, "outcome")) === "PARKED", "level 1 driven with the keyboard is PARKED");
  const status = await text(page, "status");

  const downloads = path.join(out, "downloads");
  fs.rmSync(downloads, { recursive: true, force: true });
  fs.mkdirSync(downloads, { recursive: true });
  const cdp = await page.createCDPSession();
  await cdp.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: downloads });
  await page.waitForSelector("a.recording", { timeout: 10000 });
  await page.click("a.recording");
  let file = null;
  for (let i = 0; i < 100 && !file; ++i) {
    await new Promise((r) => setTimeout(r, 100));
    file = fs.readdirSync(downloads).find((f) => f.endsWith(".replay"));
  }
  check(file !== null && file !== undefined, `the recording downloads (${file})`);
  if (file) {
    const scene = "assets/scenes/levels/level-1-straight.json";
    const got = nativeReplay([path.join(downloads, file), "--scene", scene]);
    check(got.status === 0, `the native cardemo replays the download (exit ${got.status}: ${got.stderr})`);
    const want = got.json ? `frame ${got.json.frames} hash ${got.json.hash}` : "(none)";
    check(status === want, `the page's "${status}" is the native replay's "${want}"`);
  }

  const shot = path.join(out, "page.png");
  await page.screenshot({ path: shot });
  const variance = await page.evaluate(async (data) => {
    const image = new Image();
    image.src = `data:image/png;base64,${data}`;
    await image.decode();
    const c = document.createElement("canvas");
    c.width = image.width;
    c.height = image.height;
    const g = c.getContext("2d");
    g.drawImage(image, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    let sum = 0, sum2 = 0, n = 0;
    for (let i = 0; i < px.length; i += 4) {
      const y = 0.299 * px[i] + 0.587 * px[i + 1] + 0.114 * px[i + 2];
      sum += y;
      sum2 += y * y;
      n += 1;
    }
    return sum2 / n - (sum / n) ** 2;
  }, fs.readFileSync(shot).toString("base64"));
  check(variance > 100, `the screenshot ${shot} is not blank (luma variance ${variance.toFixed(0)})`);
  await page.close();
}

async function malformed(browser) {
  const name = "page-test-bad.replay";
  fs.writeFileSync(path.join(site, name), "cardemo-replay 1\nscene assets/scenes/parking-lot.json\n120 U\n10 UX\n");
  try {
    const want = nativeReplay([name]);
    check(want.status === 2 && /^[^:]+:\d+: ./.test(want.stderr), `the native cardemo rejects ${name}: ${want.stderr}`);
    const page = await open(browser, `?replay=${name}`);
    check(await waitText(page, "status", want.stderr), `#status shows "${want.stderr}"`);
    check(await waitText(page, "outcome", "picker"), "the picker stays");
    await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
    check((await text(page, "status")) === want.stderr, "and #status keeps the error");
    await page.keyboard.press("Enter");
    check(await waitText(page, "outcome", "driving"), "and Enter still starts a level");
    await page.close();
  } finally {
    fs.rmSync(path.join(site, name), { force: true });
  }
}

async function freeDrive(browser) {
  // The lot with the car in its first free bay: 90 frames standing (the bay parks), a short drive
  // (the chain's clock starts at frame 90, the last frame standing), then standing past 180 s.
  const scene = "page-test-lot.json";
  const name = "page-test-chain.replay";
  const lot = JSON.parse(fs.readFileSync(path.join(site, "assets/scenes/parking-lot.json"), "utf8"));
  Object.assign(lot.player, { x: -40, y: 8, heading_deg: 270 });
  fs.writeFileSync(path.join(site, scene), JSON.stringify(lot));
  fs.writeFileSync(path.join(site, name), `cardemo-replay 1\nscene ${scene}\n90 .\n60 U\n60 D\n1 .\n21700 .\n`);
  try {
    const end = 90 + 180 * 120;
    const whole = nativeReplay([name, "--bay-chain"]).json;
    check(whole.bay_chain.count === 1 && whole.bay_chain.over, `natively the chain parks 1 bay, then ends (${JSON.stringify(whole.bay_chain)})`);
    const want = nativeReplay([cutReplay(name, end), "--scene", scene]).json;
    const page = await open(browser, `?replay=${name}&speed=max`);
    check(await waitText(page, "outcome", "TIME UP"), "the page's free drive ends with TIME UP");
    check(await waitText(page, "status", `frame ${want.frames} hash ${want.hash}`), `at the chain's end: native frame ${want.frames} hash ${want.hash}`);
    await page.close();
  } finally {
    fs.rmSync(path.join(site, name), { force: true });
    fs.rmSync(path.join(site, scene), { force: true });
  }
}

(async () => {
  fs.mkdirSync(out, { recursive: true });
  const browser = await puppeteer.launch({
    executablePath: "/usr/bin/chromium",
    headless: true,
    // CI runs as root; no GPU in CI: software WebGL/2D.
    args: ["--no-sandbox", "--disable-gpu", "--autoplay-policy=no-user-gesture-required"],
  });
  try {
    const only = process.env.PAGE_TEST_ONLY || "replays levelOne malformed freeDrive";
    if (only.includes("replays")) await replays(browser);
    if (only.includes("levelOne")) await levelOne(browser);
    if (only.includes("malformed")) await malformed(browser);
    if (only.includes("freeDrive")) await freeDrive(browser);
  } finally {
    await browser.close();
  }
  check(consoleErrors.length === 0, `no console error (${consoleErrors.join("; ")})`);
  console.log(`page-test: ${checks - failures.length} of ${checks} checks passed`);
  process.exit(failures.length === 0 ? 0 : 1);
})().catch((e) => {
  console.error(`page-test: ${e.stack || e}`);
  process.exit(1);
});
