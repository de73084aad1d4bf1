// Benchmarks of the page in headless Debian chromium (scripts/web-bench.sh): steps per second of
// a replay run to its end (?speed=max), and the frame time (update + draw, as src/web measures
// it) while a replay is watched in real time. Prints one line per figure; asserts nothing.
// Usage: node page-bench.js URL FAST_REPLAY FRAMES_REPLAY...
"use strict";
const puppeteer = require("puppeteer-core");

const [url, fast, ...watched] = process.argv.slice(2);
const seconds = 10;

function quantile(sorted, q) {
  return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--disable-gpu"],
  });
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800 });
  await page.goto(`${url}/index.html?replay=${fast}&speed=max`, { waitUntil: "load" });
  // The frames' own update + draw times, summed: the page's CPU time for the run.
  await page.waitForFunction(() => /^frame /.test(document.getElementById("status").textContent));
  await page.waitForFunction(() => document.getElementById("outcome").textContent !== "watching", {
    timeout: 600000,
  });
  const [frames, ms] = await page.evaluate(() => [
    Number(/^frame (\d+)/.exec(document.getElementById("status").textContent)[1]),
    Module.page.frameTimes.reduce((a, b) => a + b, 0),
  ]);
  console.log(`chromium ${fast} speed=max: ${(frames / ms / 1e3).toFixed(2)} M frames/s (${frames} frames in ${ms.toFixed(0)} ms)`);
  for (const replay of watched) {
    await page.goto(`${url}/index.html?replay=${replay}`, { waitUntil: "load" });
    await page.waitForFunction(() => /^frame /.test(document.getElementById("status").textContent));
    await page.evaluate(() => (Module.page.frameTimes.length = 0));
    await new Promise((r) => setTimeout(r, seconds * 1000));
    const times = (await page.evaluate(() => Module.page.frameTimes.slice())).sort((a, b) => a - b);
    console.log(
      `chromium ${replay} watched: ${times.length} frames in ${seconds} s, update+draw p50 ` +
        `${quantile(times, 0.5).toFixed(2)} ms, p99 ${quantile(times, 0.99).toFixed(2)} ms`,
    );
  }
  await browser.close();
})().catch((e) => {
  console.error(`page-bench: ${e.stack || e}`);
  process.exit(1);
});
