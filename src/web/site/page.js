// The page around the game (src/web): the 2D context the WebCanvas commands are replayed on,
// Web Audio, the files the game reads (served replays, opened or dropped ones, best scores in
// localStorage) and the recordings offered as downloads. No game rule lives here.
"use strict";

const page = (() => {
  const canvas = document.getElementById("game");
  const ctx = canvas.getContext("2d");
  const statusElement = document.getElementById("status");
  const outcomeElement = document.getElementById("outcome");
  const logElement = document.getElementById("log");
  const font = '"DejaVu Sans Game", sans-serif';
  const bestScoresKey = "cardemo-best-scores";
  const params = new URLSearchParams(location.search);
  const decoder = new TextDecoder();

  // Sprites, numbered as render/canvas.hpp's ImageId.
  const sprites = ["car", "wheel", "ground"].map((name) => {
    const image = new Image();
    image.src = `assets/sprites/${name}.png`;
    return image;
  });
  const tinted = new Map(); // id and RGB, packed -> the sprite multiplied by that colour

  function tintedSprite(id, r, g, b) {
    const image = sprites[id];
    if (r === 255 && g === 255 && b === 255) return image;
    const key = ((id * 256 + r) * 256 + g) * 256 + b;
    let out = tinted.get(key);
    if (out) return out;
    out = document.createElement("canvas");
    out.width = image.naturalWidth;
    out.height = image.naturalHeight;
    const c = out.getContext("2d");
    c.drawImage(image, 0, 0);
    c.globalCompositeOperation = "multiply";
    c.fillStyle = `rgb(${r},${g},${b})`;
    c.fillRect(0, 0, out.width, out.height);
    c.globalCompositeOperation = "destination-in"; // keep the sprite's own alpha
    c.drawImage(image, 0, 0);
    tinted.set(key, out);
    return out;
  }

  // Text: the bundled DejaVu Sans, as the SDL window uses; widths cached (the HUD asks each frame).
  const widths = new Map();
  function textWidth(text, px) {
    const key = `${px}|${text}`;
    let w = widths.get(key);
    if (w === undefined) {
      if (widths.size > 4096) widths.clear();
      ctx.font = `${px}px ${font}`;
      w = Math.ceil(ctx.measureText(text).width);
      widths.set(key, w);
    }
    return w;
  }

  // CSS colours by packed RGBA: a colour string is built and parsed once, not once a command.
  const colours = new Map();
  function cssColour(r, g, b, a) {
    const key = ((r * 256 + g) * 256 + b) * 256 + a;
    let css = colours.get(key);
    if (css === undefined) {
      css = `rgba(${r},${g},${b},${a / 255})`;
      colours.set(key, css);
    }
    return css;
  }

  // Replays WebCanvas's command list (web_canvas.cpp): each command is its code, an RGBA colour,
  // then clear: nothing; fill: n, n points; line: width, a, b; text: x, y, px, offset, length;
  // image: id, centre, angle, width, height. Runs of opaque fills of one colour are one path, and
  // so are runs of opaque lines of one colour and width; the context's state (colours, width,
  // font, alpha, transform) is set only when it changes.
  function drawCommands(c, texts) {
    let path = 0; // the open path: 0 none, 1 fills, 2 lines
    let pathStyle = null;
    let pathWidth = 0;
    let fillStyle = null, strokeStyle = null, lineWidth = -1, fontPx = -1, alpha = 1;
    let turned = false; // the transform is an image's, not the identity
    const endPath = () => {
      if (path === 1) ctx.fill();
      else if (path === 2) ctx.stroke();
      path = 0;
    };
    const plain = () => {
      if (turned) ctx.setTransform(1, 0, 0, 1, 0, 0);
      if (alpha !== 1) ctx.globalAlpha = 1;
      turned = false;
      alpha = 1;
    };
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.globalAlpha = 1;
    ctx.textBaseline = "top";
    let i = 0;
    while (i < c.length) {
      const op = c[i];
      const a = c[i + 4];
      const style = cssColour(c[i + 1], c[i + 2], c[i + 3], a);
      i += 5;
      if (op === 1) {
        const n = c[i++];
        if (path !== 1 || pathStyle !== style || a !== 255) {
          endPath();
          plain();
          if (fillStyle !== style) ctx.fillStyle = fillStyle = style;
          ctx.beginPath();
          path = 1;
          pathStyle = style;
        }
        ctx.moveTo(c[i], c[i + 1]);
        for (let k = 1; k < n; ++k) ctx.lineTo(c[i + 2 * k], c[i + 2 * k + 1]);
        ctx.closePath();
        i += 2 * n;
        continue;
      }
      if (op === 2) {
        const width = c[i];
        if (path !== 2 || pathStyle !== style || pathWidth !== width || a !== 255) {
          endPath();
          plain();
          if (strokeStyle !== style) ctx.strokeStyle = strokeStyle = style;
          if (lineWidth !== width) ctx.lineWidth = lineWidth = width;
          ctx.beginPath();
          path = 2;
          pathStyle = style;
          pathWidth = width;
        }
        ctx.moveTo(c[i + 1], c[i + 2]);
        ctx.lineTo(c[i + 3], c[i + 4]);
        i += 5;
        continue;
      }
      endPath();
      if (op === 0) {
        plain();
        if (fillStyle !== style) ctx.fillStyle = fillStyle = style;
        ctx.fillRect(0, 0, canvas.width, canvas.height);
      } else if (op === 3) {
        plain();
        if (fillStyle !== style) ctx.fillStyle = fillStyle = style;
        if (fontPx !== c[i + 2]) {
          fontPx = c[i + 2];
          ctx.font = `${fontPx}px ${font}`;
        }
        ctx.fillText(decoder.decode(texts.subarray(c[i + 3], c[i + 3] + c[i + 4])), c[i], c[i + 1]);
        i += 5;
      } else if (op === 4) {
        const image = tintedSprite(c[i], c[i - 4], c[i - 3], c[i - 2]);
        const w = c[i + 4], h = c[i + 5];
        const cos = Math.cos(c[i + 3]), sin = Math.sin(c[i + 3]);
        if (alpha !== a / 255) ctx.globalAlpha = alpha = a / 255;
        ctx.setTransform(cos, sin, -sin, cos, c[i + 1], c[i + 2]);
        turned = true;
        ctx.drawImage(image, -w / 2, -h / 2, w, h);
        i += 6;
      } else {
        throw new Error(`unknown canvas command ${op}`);
      }
    }
    endPath();
    plain();
  }

  // The canvas's pixels follow its size on the page.
  function fitCanvas() {
    const w = Math.max(1, Math.round(canvas.clientWidth));
    const h = Math.max(1, Math.round(canvas.clientHeight));
    if (canvas.width !== w) canvas.width = w;
    if (canvas.height !== h) canvas.height = h;
  }

  // Web Audio: the same WAVs and mix as platform/game_audio.cpp: four engine loops and the screech
  // loop always running, their gains set each frame in SDL_mixer's 129 steps; impacts and the
  // chime on at most four one-shot voices, the oldest giving way.
  const audio = { context: null, loops: [], buffers: [], voices: [] };
  const loopNames = ["engine-1", "engine-2", "engine-3", "engine-4", "screech"];
  const oneShotNames = ["impact", "chime"];
  const kVoices = 4;
  const mixerSteps = 128;
  function step(level) {
    return Number.isNaN(level) ? 0 : Math.round(Math.min(1, Math.max(0, level)) * mixerSteps) / mixerSteps;
  }
  async function loadSound(name) {
    const response = await fetch(`assets/sounds/${name}.wav`);
    return audio.context.decodeAudioData(await response.arrayBuffer());
  }
  // Browsers start sound only after a user gesture: the first key or click opens it.
  async function startAudio() {
    if (audio.context) return;
    audio.context = new AudioContext();
    try {
      const loops = await Promise.all(loopNames.map(loadSound));
      audio.buffers = await Promise.all(oneShotNames.map(loadSound));
      audio.loops = loops.map((buffer) => {
        const gain = audio.context.createGain();
        gain.gain.value = 0;
        gain.connect(audio.context.destination);
        const source = audio.context.createBufferSource();
        source.buffer = buffer;
        source.loop = true;
        source.connect(gain);
        source.start();
        return gain;
      });
    } catch (e) {
      log(`playing without sound: ${e}`);
    }
  }
  function audioLoops(engine, screech) {
    if (audio.loops.length === 0) return;
    const levels = [...engine, screech];
    const now = audio.context.currentTime;
    levels.forEach((level, k) => audio.loops[k].gain.setValueAtTime(step(level), now));
  }
  function audioOnce(sound, level) {
    if (!audio.buffers[sound]) return;
    if (audio.voices.length >= kVoices) audio.voices.shift().stop();
    const gain = audio.context.createGain();
    gain.gain.value = step(level);
    gain.connect(audio.context.destination);
    const source = audio.context.createBufferSource();
    source.buffer = audio.buffers[sound];
    source.connect(gain);
    source.onended = () => {
      const k = audio.voices.indexOf(source);
      if (k >= 0) audio.voices.splice(k, 1);
    };
    audio.voices.push(source);
    source.start();
  }
  addEventListener("keydown", startAudio);
  addEventListener("pointerdown", startAudio);

  function log(line) {
    console.log(line);
    logElement.textContent += `${line}\n`;
  }

  // Frame times (update + draw, ms) and where they went (update, C++ draw, the 2D context's
  // replay of the commands), kept for the benchmark (tests/web/page-bench.js).
  const frameTimes = [];
  const frameParts = [];
  function frameTime(ms, update, draw, flush) {
    if (frameTimes.length >= 100000) return;
    frameTimes.push(ms);
    frameParts.push([update, draw, flush]);
  }

  // Files. A path in the wasm file system is the page-relative path the user named, so that
  // errors name it as the command line would.
  function writeFile(path, bytes) {
    const slash = path.lastIndexOf("/");
    if (slash > 0) Module.FS.mkdirTree(path.slice(0, slash));
    Module.FS.writeFile(path, bytes);
  }
  // The scene line of a replay's text, resolved relative to the replay (io/replay_text does the
  // real parsing; this only finds which file to fetch).
  function sceneOf(path, text) {
    for (const raw of text.split("\n")) {
      const line = raw.replace(/#.*/, "").trim();
      if (!line.startsWith("scene ")) continue;
      const scene = line.slice(6).trim();
      if (scene.startsWith("/")) return scene;
      const slash = path.lastIndexOf("/");
      return slash >= 0 ? `${path.slice(0, slash + 1)}${scene}` : scene;
    }
    return null;
  }
  async function fetchInto(path) {
    try {
      const response = await fetch(path);
      if (!response.ok) return null;
      const bytes = new Uint8Array(await response.arrayBuffer());
      writeFile(path, bytes);
      return bytes;
    } catch (e) {
      return null; // the game then says the file cannot be opened
    }
  }
  async function fetchReplay(path) {
    const bytes = await fetchInto(path);
    if (!bytes) return;
    const scene = sceneOf(path, decoder.decode(bytes));
    if (scene) await fetchInto(scene);
  }

  // A replay opened from disk is written into the bundled replays' folder, so that the usual
  // `scene ../scenes/...` line finds the bundled scene, and watched under its own name.
  const uploads = "/assets/replays";
  async function watchFile(file) {
    const name = file.name.replace(/[/\\]/g, "_");
    writeFile(`${uploads}/${name}`, new Uint8Array(await file.arrayBuffer()));
    Module.FS.chdir(uploads);
    try {
      Module.ccall("cardemo_watch", null, ["string", "number"], [name, 0]);
    } finally {
      Module.FS.chdir("/");
    }
    canvas.focus();
  }
  document.getElementById("open").addEventListener("change", (e) => {
    if (e.target.files.length > 0) watchFile(e.target.files[0]);
    e.target.value = "";
  });
  addEventListener("dragover", (e) => e.preventDefault());
  addEventListener("drop", (e) => {
    e.preventDefault();
    if (e.dataTransfer.files.length > 0) watchFile(e.dataTransfer.files[0]);
  });

  // Each attempt's recording, published by the game, offered as a download.
  const recordings = [];
  function offerRecording(path, scene) {
    const bytes = Module.FS.readFile(path);
    const name = `${scene}-${path.slice(path.lastIndexOf("/") + 1)}`;
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([bytes], { type: "text/plain" }));
    link.download = name;
    link.textContent = `download ${name}`;
    link.className = "recording";
    document.getElementById("recordings").prepend(link);
    recordings.push({ name, text: decoder.decode(bytes) });
  }

  // Best scores: the native file's JSON, kept in localStorage between visits.
  function restoreBestScores(path) {
    const text = localStorage.getItem(bestScoresKey);
    if (text !== null) writeFile(path, text);
  }
  function saveBestScores(path) {
    try {
      localStorage.setItem(bestScoresKey, Module.FS.readFile(path, { encoding: "utf8" }));
    } catch (e) {
      // no file yet: nothing parked
    }
  }

  async function start() {
    await Promise.all([
      document.fonts.load(`16px ${font}`),
      ...sprites.map((image) => image.decode().catch(() => log(`cannot load ${image.src}`))),
    ]);
    Module.FS.chdir("/");
    restoreBestScores("/home/web_user/best-scores.json");
    const replay = params.get("replay") ?? "";
    if (replay) await fetchReplay(replay);
    fitCanvas();
    Module.ccall("cardemo_start", null, ["string", "number"], [replay, params.get("speed") === "max" ? 1 : 0]);
    canvas.focus();
  }

  return {
    canvasWidth: () => (fitCanvas(), canvas.width),
    canvasHeight: () => canvas.height,
    drawCommands,
    textWidth,
    textHeight: (px) => Math.ceil(px * 1.164), // DejaVu Sans: ascent + descent
    hasImage: (id) => sprites[id].complete && sprites[id].naturalWidth > 0,
    audioLoops,
    audioOnce,
    setStatus: (text) => (statusElement.textContent = text),
    setOutcome: (text) => (outcomeElement.textContent = text),
    log,
    frameTime,
    frameTimes,
    frameParts,
    fetchReplay,
    offerRecording,
    recordings,
    saveBestScores,
    start,
  };
})();

var Module = {
  page,
  print: (line) => page.log(line),
  printErr: (line) => page.log(line),
  onRuntimeInitialized: () => page.start(),
};
