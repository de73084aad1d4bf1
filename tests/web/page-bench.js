// Benchmarks of the page in headless Debian chromium (scripts/web-bench.sh): the CPU time of a
// headless replay run in the page (the same run as `cardemo replay`), and the frame time (update +
// draw, as src/web measures it) while a replay is watched in real time. Prints one line per
// figure; asserts nothing.
// Usage: node page-bench.js URL RUNS LONG_REPLAY ONE_FRAME_REPLAY WATCHED_REPLAY...
"use strict";
const puppeteer = require("puppeteer-core");

const [url, runsText, long, oneFrame, ...watched] = process.argv.slice(2);
const runs = Number(runsText);
const seconds = 10;

function quantile(sorted, q) {
  return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
}
function median(values) {
  return quantile([...values].sort((a, b) => a - b), 0.5);
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--disable-gpu"],
  });
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800 });
  // The main thread's CPU time (thread ticks, not wall time: the machine is shared).
  const cdp = await page.target().createCDPSession();
  await cdp.send("Performance.enable", { timeDomain: "threadTicks" });
  const taskSeconds = async () =>
    (await cdp.send("Performance.getMetrics")).metrics.find((m) => m.name === "TaskDuration").value;

  await page.goto(`${url}/index.html`, { waitUntil: "load" });
  await page.waitForFunction(() => document.getElementById("outcome").textContent === "picker");
  await page.evaluate((paths) => Promise.all(paths.map((p) => Module.page.fetchReplay(p))), [long, oneFrame]);
  // One headless run of `path` in the page: its main-thread CPU seconds and its result line.
  const run = async (path) => {
    const before = await taskSeconds();
    const result = await page.evaluate((p) => Module.ccall("cardemo_run_replay", "string", ["string"], [p]), path);
    return [(await taskSeconds()) - before, result];
  };
  const full = [], load = [];
  let result = "";
  for (let k = 0; k < runs; ++k) {
    load.push((await run(oneFrame))[0]);
    const [s, r] = await run(long);
    full.push(s);
    result = r;
  }
  const frames = Number(/^frame (\d+)/.exec(result)?.[1]);
  if (!frames) throw new Error(`${long}: ${result}`);
  const cpu = median(full), less = median(load);
  console.log(
    `chromium ${long}: ${(frames / (cpu - less) / 1e6).toFixed(2)} M frames/s ` +
      `(${cpu.toFixed(2)} s CPU, less ${less.toFixed(2)} s load, median of ${runs}; ${result})`,
  );

  for (const replay of watched) {
    await page.goto(`${url}/index.html?replay=${replay}`, { waitUntil: "load" });
    await page.waitForFunction(() => /^frame /.test(document.getElementById("status").textContent));
    await page.evaluate(() => {
      Module.page.frameTimes.length = 0;
      Module.page.frameParts.length = 0;
    });
    await new Promise((r) => setTimeout(r, seconds * 1000));
    const [frames, parts] = await page.evaluate(() => [Module.page.frameTimes.slice(), Module.page.frameParts.slice()]);
    const times = [...frames].sort((a, b) => a - b);
    const p99 = quantile(times, 0.99);
    // Where the time of the slowest frames (p99 and up) went: update, C++ draw, the 2D context.
    const slow = parts.filter((_, k) => frames[k] >= p99);
    const mean = (j, rows) => (rows.reduce((a, r) => a + r[j], 0) / rows.length).toFixed(2);
    console.log(
      `chromium ${replay} watched: ${times.length} frames in ${seconds} s, update+draw p50 ` +
        `${quantile(times, 0.5).toFixed(2)} ms, p99 ${p99.toFixed(2)} ms; mean update/draw/context ` +
        `${mean(0, parts)}/${mean(1, parts)}/${mean(2, parts)} ms, of the p99 frames ` +
        `${mean(0, slow)}/${mean(1, slow)}/${mean(2, slow)} ms`,
    );
  }
  await browser.close();
})().catch((e) => {
  console.error(`page-bench: ${e.stack || e}`);
  process.exit(1);
});
