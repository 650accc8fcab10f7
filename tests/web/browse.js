// The web page in a real headless Chromium (puppeteer-core on Debian's chromium), driven
// as a student drives it. check.py gives the jobs and judges the answers:
//
//   node browse.js BASE describe OUT       the labs as the page describes them
//   node browse.js BASE numbers CASES OUT  each case's address loaded afresh: its
//                                          console's errors, the page's JSON, the
//                                          inputs' fields as shown
//   node browse.js BASE behaviour OUT      a broken rule typed, a link, touch and keys,
//                                          the canvas read back
//   node browse.js BASE screenshot QUERY WxH[-touch] OUT [SECONDS]   the page as shown
"use strict";
const fs = require("fs");
const puppeteer = require("puppeteer-core");

const [base, mode, ...rest] = process.argv.slice(2);
const chromium = process.env.RIGID_CHROMIUM || "/usr/bin/chromium";

async function browser() {
  return puppeteer.launch({
    executablePath: chromium,
    headless: true,
    // in a container /dev/shm is often 64 MB: Chromium then keeps its shared memory in /tmp
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           "--disable-dev-shm-usage", "--hide-scrollbars"],
  });
}

// A page whose console errors and uncaught exceptions are kept.
async function openPage(b, width = 1280, height = 720, touch = false) {
  const page = await b.newPage();
  await page.setViewport({ width, height, hasTouch: touch, isMobile: touch });
  page.problems = [];
  page.on("console", (m) => { if (m.type() === "error") page.problems.push(m.text()); });
  page.on("pageerror", (e) => page.problems.push(`uncaught: ${e.message || e}`));
  page.on("requestfailed", (r) => page.problems.push(`request failed: ${r.url()}`));
  return page;
}

// Loads the page at `query` and waits for its first frame.
async function load(page, query) {
  await page.goto(`${base}/index.html${query ? "?" + query : ""}`, { waitUntil: "load" });
  await page.waitForFunction(() => Number(document.body.dataset.frames || 0) >= 1,
                             { timeout: 60000 });
}

async function describe(out) {
  const b = await browser();
  const page = await openPage(b);
  await load(page, "");
  const labs = await page.evaluate(() => window.rigidlab.labs);
  fs.writeFileSync(out, JSON.stringify(labs));
  await b.close();
}

async function numbers(casesFile, out) {
  const cases = JSON.parse(fs.readFileSync(casesFile, "utf8"));
  const b = await browser();
  const page = await openPage(b);
  const answers = [];
  for (const c of cases) {
    page.problems = [];
    await load(page, c.query);
    const got = await page.evaluate(() => ({
      json: window.rigidlab.page.json(),
      status: document.getElementById("status").textContent,
      fields: [...document.querySelectorAll("#inputs input, #inputs select")]
        .map((e) => [e.id, e.type === "checkbox" ? String(e.checked) : e.value]),
      command: document.getElementById("command").value,
    }));
    answers.push({ id: c.id, problems: page.problems, ...got });
  }
  fs.writeFileSync(out, JSON.stringify(answers));
  await b.close();
}

// What happens when a student does things: each a named outcome for check.py.
async function behaviour(out) {
  const b = await browser();
  const result = {};
  let page = await openPage(b);

  // a broken rule typed in a field: the rule beside it, the view's state kept
  await load(page, "lab=top_nutation");
  const before = await page.evaluate(() => window.rigidlab.shown.command);
  await page.click("#in-mass", { clickCount: 3 });
  await page.keyboard.type("-2");
  await page.keyboard.press("Enter");
  result.refusal = await page.evaluate(() => ({
    error: document.getElementById("in-mass-error").textContent,
    invalid: document.getElementById("in-mass").getAttribute("aria-invalid"),
    status: document.getElementById("status").textContent,
    command: window.rigidlab.shown.command,
    address: location.search,
  }));
  result.refusal.before = before;
  // then a valid one: taken, the error gone, the address holding it
  await page.click("#in-mass", { clickCount: 3 });
  await page.keyboard.type("3");
  await page.keyboard.press("Enter");
  result.accepted = await page.evaluate(() => ({
    error: document.getElementById("in-mass-error").textContent,
    invalid: document.getElementById("in-mass").getAttribute("aria-invalid"),
    command: window.rigidlab.shown.command,
    address: location.search,
  }));

  // a link to no lab, or with an input the lab has not: said, and a lab shown
  await load(page, "lab=nosuch&mass=2");
  result.unknownLab = await page.evaluate(() => document.getElementById("status").textContent);
  await load(page, "lab=poinsot&spin-rpm=2");
  result.unknownInput = await page.evaluate(() => ({
    status: document.getElementById("status").textContent,
    command: window.rigidlab.shown.command,
  }));

  // a link with inputs: the fields show them, and a reload shows the same
  await load(page, "lab=football&alpha-deg=12.5&preset=frisbee");
  result.link = await page.evaluate(() => ({
    alpha: document.getElementById("in-alpha_deg") && document.getElementById("in-alpha_deg").value,
    command: window.rigidlab.shown.command,
    address: location.search,
  }));
  // offline once loaded: another lab opened and computed with the network gone
  await page.setOfflineMode(true);
  result.offline = await page.evaluate(() => {
    const pick = document.getElementById("lab");
    pick.value = "tennis_racquet";
    pick.dispatchEvent(new Event("change"));
    return window.rigidlab.shown.lab;
  });
  await page.setOfflineMode(false);
  result.problems = page.problems;

  // the keyboard: Tab reaches the fields, which have labels; keys turn the view
  result.keyboard = await page.evaluate(() => {
    const unlabelled = [...document.querySelectorAll("input, select, button, canvas")]
      .filter((e) => !e.closest("[hidden]"))
      .filter((e) => !(e.labels && e.labels.length) && !e.getAttribute("aria-label") &&
                     !(e.textContent || "").trim())
      .map((e) => e.id || e.tagName);
    return { unlabelled };
  });
  await page.focus("#canvas");
  const orbitBefore = await page.evaluate(() => window.rigidlab.page.viewPng(64, 48).length);
  await page.keyboard.press("ArrowLeft");
  await page.keyboard.press("+");
  await page.keyboard.press(" ");
  result.keys = await page.evaluate(() => ({ playing: window.rigidlab.playing }));
  result.keys.drew = orbitBefore > 0;
  await page.close();

  // touch: a tap on a field focuses it; a swipe on the canvas turns the view
  page = await openPage(b, 820, 1180, true);
  await load(page, "lab=poinsot");
  await page.tap("#in-mass");
  result.touch = await page.evaluate(() => ({ focused: document.activeElement.id }));
  const box = await page.evaluate(() => {
    const canvas = document.getElementById("canvas");
    canvas.scrollIntoView();  // the tap on a field scrolled the page to it
    const r = canvas.getBoundingClientRect();
    return { x: r.left + r.width / 2, y: r.top + r.height / 4 };
  });
  const shot = () => page.evaluate(() => document.getElementById("canvas").toDataURL());
  const still = await shot();
  await page.touchscreen.touchStart(box.x, box.y);
  await page.touchscreen.touchMove(box.x + 80, box.y + 10);
  await page.touchscreen.touchEnd();
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  result.touch.turned = (await shot()) !== still;
  result.touch.layout = await page.evaluate(() => {
    const v = document.getElementById("view").getBoundingClientRect();
    const c = document.getElementById("controls").getBoundingClientRect();
    return { stacked: c.top >= v.bottom - 1, overflow: document.documentElement.scrollWidth > window.innerWidth };
  });
  result.touchProblems = page.problems;
  await page.close();

  // the scene and a plot drawn into the canvas and read back, for check.py to hold to
  // the command line's figures
  page = await openPage(b);
  await load(page, "lab=top_nutation");
  result.figures = await page.evaluate(() => {
    const canvas = document.getElementById("canvas");
    const shots = {};
    for (const name of ["top", "potential"]) {
      canvas.width = 800;
      canvas.height = 600;
      const why = window.rigidlab.page.drawFigure(name, 800, 600, 600);
      shots[name] = why || canvas.toDataURL("image/png");
    }
    return shots;
  });
  await page.close();

  fs.writeFileSync(out, JSON.stringify(result, null, 1));
  await b.close();
}

// The bench's measurements (bench/web_bench.py), at 1280x720: the first frame from
// navigation with a warm cache, each lab's compute() timed in WebAssembly, the frame
// interval while a motion plays, and an input change to its frame.
async function bench(out) {
  const b = await browser();
  const page = await openPage(b, 1280, 720);
  await load(page, "lab=top_nutation");
  const result = { first_frame_ms: [], labs: {} };
  for (let k = 0; k < 5; ++k) {
    await page.reload({ waitUntil: "load" });
    await page.waitForFunction(() => window.rigidlab && window.rigidlab.firstFrame, { timeout: 60000 });
    result.first_frame_ms.push(await page.evaluate(() => window.rigidlab.firstFrame));
  }
  const names = await page.evaluate(() => window.rigidlab.labs.map((l) => l.name));
  for (const name of names) {
    await load(page, `lab=${name}`);
    result.labs[name] = await page.evaluate(async (lab) => {
      const st = window.rigidlab;
      const nextFrame = () => new Promise((r) => requestAnimationFrame(r));
      // compute(), whole, at the defaults: 21 batches
      const compute = JSON.parse(st.page.computeSeconds(lab, 21));
      // an input changed: to the frame that shows it, and to the whole report's
      // a number 1 % off its default and back, or where no number has a default, a
      // choice's second word and back
      let input = st.lab.inputs.find((i) => i.kind === "number" && !i.numerical &&
                                     i.has_default && Number(i.default) > 0);
      let values = input ? [String(Number(input.default) * 1.01), input.default] : null;
      if (!input) {
        input = st.lab.inputs.find((i) => i.kind === "choice" && !i.numerical && i.choices.length > 1);
        values = input ? [input.choices[1], input.choices[0]] : null;
      }
      // the first two changes apart: the first runs code the browser has not compiled yet
      const toFrame = [], toWhole = [];
      if (input) {
        const control = document.getElementById("in-" + input.key);
        for (let k = 0; k < 14; ++k) {
          control.value = values[k % 2];
          const before = Number(document.body.dataset.frames);
          const t0 = performance.now();
          control.dispatchEvent(new Event("change"));
          while (Number(document.body.dataset.frames) <= before) await nextFrame();
          toFrame.push(performance.now() - t0);
          while (st.shown.pending) await nextFrame();
          toWhole.push(performance.now() - t0);
        }
      }
      // the motion played for two seconds: the interval between frames
      const intervals = [];
      if (st.shown.seconds > 0) {
        st.playing = true;
        let last = await nextFrame();
        const end = last + 2000;
        while (last < end) {
          const now = await nextFrame();
          intervals.push(now - last);
          last = now;
        }
        st.playing = false;
      }
      const first = toFrame.splice(0, 2);
      toWhole.splice(0, 2);
      return { compute_s: compute, input_to_frame_ms: toFrame, input_to_whole_ms: toWhole,
               first_input_ms: first,
               frame_interval_ms: intervals, input: input ? input.flag : "" };
    }, name);
  }
  result.problems = page.problems;
  fs.writeFileSync(out, JSON.stringify(result));
  await b.close();
}

// The page at an address and a size, as the README shows it: WxH, or WxH-touch for a
// tablet; the motion played to `seconds` first where given.
async function screenshot(query, size, out, seconds) {
  const [w, h] = size.split("-")[0].split("x").map(Number);
  const b = await browser();
  const page = await openPage(b, w, h, size.endsWith("-touch"));
  await load(page, query);
  if (seconds) {
    await page.evaluate((t) => {
      window.rigidlab.time = t;
      window.rigidlab.page.seek(t);
      window.rigidlab.dirty = true;
    }, Number(seconds));
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  }
  await page.screenshot({ path: out });
  if (page.problems.length) console.error(page.problems.join("\n"));
  await b.close();
}

const jobs = { describe, numbers, behaviour, bench, screenshot };
if (!jobs[mode]) {
  console.error(`browse.js: unknown job '${mode}' (describe, numbers, behaviour)`);
  process.exit(2);
}
jobs[mode](...rest).catch((e) => {
  console.error(`browse.js ${mode}: ${e.stack || e}`);
  process.exit(1);
});
