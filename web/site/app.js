// The page around the WebAssembly module (page.cpp): each lab's inputs as labelled
// fields made from its input table, the view drawn into one WebGL2 canvas, the report
// as text a reader can select, and the address holding the lab and its inputs in the
// command line's own spelling (?lab=top_nutation&spin-rpm=300). Every rule, number and
// file comes from the module; this script only lays them out and passes text along.
"use strict";

(() => {
  const $ = (id) => document.getElementById(id);
  const state = {
    page: null, labs: [], lab: null, shown: null, refusals: {}, playing: false,
    time: 0, speed: 1, lastFrame: 0, dirty: true, pollNext: false,
    pointers: new Map(), pinch: 0,
  };

  // ---- the address -------------------------------------------------------------------

  // The address's inputs as [option, text] pairs: "spin-rpm=300" is --spin-rpm 300, a
  // name alone a switch that is on.
  function addressInputs(params) {
    const given = [];
    for (const [name, value] of params) {
      if (name !== "lab") given.push(["--" + name, value]);
    }
    return given;
  }

  function addressOf(shown) {
    const params = new URLSearchParams();
    params.set("lab", shown.lab);
    for (const arg of shown.arguments) {
      const eq = arg.indexOf("=");
      const name = (eq < 0 ? arg : arg.slice(0, eq)).replace(/^--/, "");
      params.append(name, eq < 0 ? "" : arg.slice(eq + 1));
    }
    // commas and the switch's bare name read better unescaped
    const query = params.toString().replace(/%2C/g, ",").replace(/=(&|$)/g, "$1");
    return location.pathname + "?" + query;
  }

  // ---- the inputs --------------------------------------------------------------------

  function fieldId(input) { return "in-" + input.key; }

  function makeField(input, index) {
    const row = document.createElement("div");
    row.className = "field";
    const id = fieldId(input);
    const label = document.createElement("label");
    label.htmlFor = id;
    label.textContent = input.help + (input.unit && input.unit !== "1" ? ` [${input.unit}]` : "");
    let control;
    if (input.kind === "choice") {
      control = document.createElement("select");
      for (const c of input.choices) control.add(new Option(c, c));
    } else if (input.kind === "flag") {
      control = document.createElement("input");
      control.type = "checkbox";
      row.classList.add("switch");
    } else {
      control = document.createElement("input");
      control.type = "text";
      control.inputMode = input.kind === "number" ? "decimal" : "text";
      control.autocomplete = "off";
      control.spellcheck = false;
    }
    control.id = id;
    control.dataset.index = index;
    const rule = document.createElement("p");
    rule.className = "rule";
    rule.id = id + "-rule";
    const words = input.words.length ? ` or ${input.words.join(", ")}` : "";
    rule.textContent = [input.flag, input.range + words, input.lab_default]
      .filter((t) => t).join(" · ");
    const error = document.createElement("p");
    error.className = "error";
    error.id = id + "-error";
    error.setAttribute("aria-live", "assertive");
    control.setAttribute("aria-describedby", `${rule.id} ${error.id}`);
    const commit = () => setInput(input, control);
    control.addEventListener("change", commit);
    control.addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); commit(); } });
    if (input.kind === "flag") { row.append(control, label); } else { row.append(label, control); }
    row.append(rule, error);
    return row;
  }

  function buildForm(lab) {
    const form = $("inputs");
    form.replaceChildren();
    const physical = lab.inputs.map((input, i) => [input, i]).filter(([input]) => !input.numerical);
    const numerical = lab.inputs.map((input, i) => [input, i]).filter(([input]) => input.numerical);
    for (const [input, i] of physical) form.append(makeField(input, i));
    if (numerical.length) {
      const group = document.createElement("details");
      const summary = document.createElement("summary");
      summary.textContent = "How it is computed";
      group.append(summary);
      for (const [input, i] of numerical) group.append(makeField(input, i));
      form.append(group);
    }
  }

  function controlText(input, control) {
    if (input.kind === "flag") return control.checked ? "on" : "off";
    return control.value.trim();
  }

  function showRefusal(refusal, control) {
    const names = refusal.inputs && refusal.inputs.length ? refusal.inputs : [];
    const lab = state.lab;
    const targets = names.map((flag) => lab.inputs.find((i) => i.flag === flag)).filter((i) => i);
    const ids = targets.length ? targets.map(fieldId) : control ? [control.id] : [];
    for (const id of ids) {
      $(id).setAttribute("aria-invalid", "true");
      $(id + "-error").textContent = refusal.refused;
      state.refusals[id] = true;
    }
    say(refusal.refused, true);
  }

  function clearRefusals() {
    for (const id of Object.keys(state.refusals)) {
      const control = $(id);
      if (control) control.removeAttribute("aria-invalid");
      const error = $(id + "-error");
      if (error) error.textContent = "";
    }
    state.refusals = {};
  }

  function setInput(input, control) {
    const text = controlText(input, control);
    const out = JSON.parse(state.page.set(input.flag, text));
    clearRefusals();
    if (out.refused) {
      showRefusal(out, control);
      return;  // the last valid state stays shown; the field keeps what was typed
    }
    say("");
    changed();
  }

  function fillForm() {
    const shown = state.shown;
    state.lab.inputs.forEach((input, i) => {
      const control = $(fieldId(input));
      if (!control || state.refusals[control.id]) return;
      if (input.kind === "flag") control.checked = shown.values[i] === "on";
      else if (document.activeElement !== control) control.value = shown.values[i];
    });
  }

  // ---- what the report says ----------------------------------------------------------

  function fillSelect(select, names, keep) {
    const before = select.value;
    select.replaceChildren(...names.map((n, i) => new Option(n, String(i))));
    if (keep && before !== "" && names.length > Number(before)) select.value = before;
    select.disabled = names.length === 0;
    // a view the lab has none of is not offered (its label with it)
    const inView = select.closest(".view-pick");
    if (inView) {
      select.hidden = names.length === 0;
      const label = inView.querySelector(`label[for="${select.id}"]`);
      if (label) label.hidden = select.hidden;
    }
  }

  function renderReport() {
    const shown = state.shown;
    document.title = `rigidlab: ${shown.title}`;
    $("lab-title").textContent = shown.title;
    const results = shown.report.results || {};
    $("answer").textContent = results.answer || "";
    $("pending").hidden = !shown.pending;
    const body = $("table").tBodies[0];
    body.replaceChildren();
    // the table as the command line prints it, but for its answer, shown above it
    const rows = shown.rows.filter((r, i, all) => r.key !== "answer" &&
      !(r.heading && all[i + 1] && all[i + 1].key === "answer"));
    for (const row of rows) {
      const tr = body.insertRow();
      if (row.heading) {
        const th = document.createElement("th");
        th.colSpan = 4;
        th.scope = "rowgroup";
        th.textContent = row.label;
        tr.append(th);
        tr.className = "heading";
        continue;
      }
      const label = document.createElement("th");
      label.scope = "row";
      label.textContent = row.label;
      tr.append(label);
      for (const text of [row.value, row.unit, [row.textbook, row.remark].filter((t) => t).join(" ")]) {
        const td = tr.insertCell();
        td.textContent = text;
        if (text.length > 24) td.className = "long";
      }
    }
    const notes = $("notes");
    notes.replaceChildren(...(shown.report.notes || []).map((n) => {
      const li = document.createElement("li");
      li.textContent = n;
      if (n.startsWith("errata:")) li.className = "erratum";
      return li;
    }));
    $("command").value = shown.command;
    fillSelect($("scene-choice"), shown.scenes, true);
    fillSelect($("plot-choice"), shown.plots, true);
    fillSelect($("figure"), shown.figures.map((f) => f.name), true);
    $("save-csv").disabled = $("save-csv-metadata").disabled = !shown.has_series;
    const seconds = shown.seconds;
    $("playbar").hidden = !(seconds > 0);
    $("time").max = String(seconds);
    $("save-view").disabled = shown.scenes.length === 0;
    renderParts();
  }

  function refresh() {
    state.shown = JSON.parse(state.page.state());
    renderReport();
    fillForm();
    history.replaceState(null, "", addressOf(state.shown));
    state.pollNext = state.shown.pending;
    state.dirty = true;
  }

  function changed() {
    state.time = Math.min(state.time, state.page.seconds());
    refresh();
  }

  // ---- opening a lab -----------------------------------------------------------------

  function openLab(name, given) {
    const known = state.labs.find((l) => l.name === name);
    const lab = known || state.labs[0];
    state.lab = lab;
    $("lab").value = lab.name;
    buildForm(lab);
    clearRefusals();
    const out = JSON.parse(state.page.open(lab.name, JSON.stringify(known ? given : [])));
    state.time = 0;
    state.page.seek(0);
    refresh();
    if (!known) {
      const names = state.labs.map((l) => l.name).join(", ");
      say(`lab: no lab named '${name}' (one of ${names}), so ${lab.name} is shown`, true);
    } else if (out.refused) {
      showRefusal(out, null);
      say(`${out.refused}: the link's inputs were refused, so the text's example is shown`, true);
    } else {
      say("");
    }
  }

  // ---- the view ----------------------------------------------------------------------

  // The scene and the plot side by side where the view is wider than 0.8 of the window's height
  // (a laptop, a tablet held sideways), one over the other where it is not (a phone, a
  // tablet held upright): each then as large as the screen lets it be.
  function layout() {
    const canvas = $("canvas");
    const ratio = window.devicePixelRatio || 1;
    const cssWidth = canvas.clientWidth;
    const wide = cssWidth >= 600 && cssWidth > 0.8 * window.innerHeight;
    const hasPlot = state.shown && state.shown.plots.length > 0;
    const hasScene = state.shown && state.shown.scenes.length > 0;
    let cssHeight;
    if (wide) cssHeight = Math.round(Math.min(cssWidth * 0.5, Math.max(360, window.innerHeight * 0.62)));
    // stacked: the scene a little taller than wide, so that on a phone its legend leaves
    // the body room (the camera is fitted clear of it), the plot under it
    else cssHeight = Math.round(cssWidth * (hasPlot && hasScene ? 1.05 + 0.75 : 0.9));
    canvas.style.height = cssHeight + "px";
    const w = Math.max(1, Math.round(cssWidth * ratio));
    const h = Math.max(1, Math.round(cssHeight * ratio));
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
      state.dirty = true;
    }
    let scene = [0, 0, w, h];
    let plot = [0, 0, 0, 0];
    if (hasPlot && hasScene) {
      if (wide) {
        const split = Math.round(w * 0.52);
        scene = [0, 0, split, h];
        plot = [split, 0, w - split, h];
      } else {
        const split = Math.round(h * 1.05 / 1.8);
        scene = [0, 0, w, split];
        plot = [0, split, w, h - split];
      }
    } else if (hasPlot) {
      plot = scene;
      scene = [0, 0, 0, 0];
    }
    state.rects = { scene, plot, w, h };
  }

  function frame(now) {
    const dt = state.lastFrame ? (now - state.lastFrame) / 1000 : 0;
    state.lastFrame = now;
    if (state.pollNext) {
      // the whole report, computed after the preview was drawn
      state.pollNext = false;
      if (state.page.poll()) refresh();
    }
    const seconds = state.shown ? state.shown.seconds : 0;
    if (state.playing && seconds > 0) {
      state.time += dt * state.speed * Math.max(1, seconds / 100);
      if (state.time > seconds) state.time = 0;
      state.page.seek(state.time);
      state.dirty = true;
    }
    layout();
    if (state.dirty && state.shown) {
      const { scene, plot, w, h } = state.rects;
      state.page.textPx(13 * (window.devicePixelRatio || 1));
      const why = state.page.draw(...scene, ...plot, w, h);
      if (why) say(`The view cannot be drawn: ${why}`, true);
      state.dirty = false;
      $("time").value = String(state.time);
      $("time-text").textContent = `t = ${state.time.toPrecision(4)} s`;
      document.body.dataset.frames = String(Number(document.body.dataset.frames || 0) + 1);
      if (!state.firstFrame) state.firstFrame = performance.now();  // from navigation start
    }
    requestAnimationFrame(frame);
  }

  // The scene's parts (its legend's entries) as switches, and the legend itself.
  function renderParts() {
    const box = $("parts");
    const { parts, legend } = JSON.parse(state.page.parts());
    const row = (id, text, checked, onChange) => {
      const label = document.createElement("label");
      const input = document.createElement("input");
      input.type = "checkbox";
      input.id = id;
      input.checked = checked;
      input.addEventListener("change", () => { onChange(); state.dirty = true; });
      label.append(input, " ", text);
      return label;
    };
    box.replaceChildren(
      row("part-legend", "the legend", legend, () => state.page.toggleLegend()),
      ...parts.map(([name, shown], i) =>
        row(`part-${i}`, name, shown, () => state.page.togglePart(name))));
    $("parts-box").hidden = parts.length === 0;
  }

  function setPlaying(on) {
    state.playing = on;
    $("play").textContent = on ? "Pause" : "Play";
    $("play").setAttribute("aria-pressed", String(on));
  }

  function bindView() {
    const canvas = $("canvas");
    canvas.addEventListener("pointerdown", (e) => {
      canvas.setPointerCapture(e.pointerId);
      state.pointers.set(e.pointerId, [e.clientX, e.clientY]);
      state.page.interacting(true);
    });
    canvas.addEventListener("pointermove", (e) => {
      const last = state.pointers.get(e.pointerId);
      if (!last) return;
      const ratio = window.devicePixelRatio || 1;
      if (state.pointers.size === 1) {
        state.page.turn((e.clientX - last[0]) * ratio, (e.clientY - last[1]) * ratio,
                        state.rects.scene[3] || state.rects.h);
      }
      state.pointers.set(e.pointerId, [e.clientX, e.clientY]);
      if (state.pointers.size === 2) {
        const [a, b] = [...state.pointers.values()];
        const d = Math.hypot(a[0] - b[0], a[1] - b[1]);
        if (state.pinch > 0 && d > 0) state.page.zoom(d / state.pinch);
        state.pinch = d;
      }
      state.dirty = true;
    });
    const up = (e) => {
      state.pointers.delete(e.pointerId);
      state.pinch = 0;
      if (state.pointers.size === 0) state.page.interacting(false);
      state.dirty = true;
    };
    canvas.addEventListener("pointerup", up);
    canvas.addEventListener("pointercancel", up);
    canvas.addEventListener("wheel", (e) => {
      e.preventDefault();
      state.page.wheel(-Math.sign(e.deltaY));
      state.dirty = true;
    }, { passive: false });
    canvas.addEventListener("keydown", (e) => {
      const turns = { ArrowLeft: [-5, 0], ArrowRight: [5, 0], ArrowUp: [0, 5], ArrowDown: [0, -5] };
      if (turns[e.key]) state.page.turnDegrees(...turns[e.key]);
      else if (e.key === "+" || e.key === "=") state.page.wheel(1);
      else if (e.key === "-") state.page.wheel(-1);
      else if (e.key === " ") setPlaying(!state.playing);
      else return;
      e.preventDefault();
      state.dirty = true;
    });
    $("play").addEventListener("click", () => setPlaying(!state.playing));
    $("time").addEventListener("input", () => {
      state.time = Number($("time").value);
      state.page.seek(state.time);
      state.dirty = true;
    });
    $("speed").addEventListener("change", () => { state.speed = Number($("speed").value); });
    $("scene-choice").addEventListener("change", () => {
      state.page.show(true, Number($("scene-choice").value));
      renderParts();
      state.dirty = true;
    });
    $("plot-choice").addEventListener("change", () => {
      state.page.show(false, Number($("plot-choice").value));
      state.dirty = true;
    });
    $("reset-view").addEventListener("click", () => { state.page.resetView(); state.dirty = true; });
    window.addEventListener("resize", () => { state.dirty = true; });
  }

  // ---- taking it away ----------------------------------------------------------------

  function say(text, error = false) {
    $("status").textContent = text;
    $("status").classList.toggle("error", error);
  }

  function download(name, data, type) {
    const url = URL.createObjectURL(new Blob([data], { type }));
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 0);
    say(`Saved ${name}`);
  }

  async function copy(text, what) {
    try {
      await navigator.clipboard.writeText(text);
      say(`Copied ${what}`);
    } catch (e) {
      $("command").select();
      say(`Select and copy ${what} by hand (the browser refused the clipboard)`, true);
    }
  }

  function figureSize() {
    const out = JSON.parse(state.page.figureSize($("figure-size").value));
    if (out.refused) {
      $("figure-size").setAttribute("aria-invalid", "true");
      say(out.refused, true);
      return null;
    }
    $("figure-size").removeAttribute("aria-invalid");
    return out;
  }

  function bindExports() {
    const stem = () => state.shown.lab;
    $("copy-command").addEventListener("click", () => copy(state.shown.command, "the command line"));
    $("copy-link").addEventListener("click", () => copy(location.href, "the link"));
    $("save-json").addEventListener("click", () =>
      download(`${stem()}.json`, state.page.json(), "application/json"));
    $("save-csv").addEventListener("click", () =>
      download(`${stem()}.csv`, state.page.csv(), "text/csv"));
    $("save-csv-metadata").addEventListener("click", () =>
      download(`${stem()}.csv-metadata.json`, state.page.csvMetadata(`${stem()}.csv`),
               "application/csvm+json"));
    $("save-figure").addEventListener("click", () => {
      const size = figureSize();
      const name = state.shown.figures[Number($("figure").value)];
      if (!size || !name) return;
      const png = state.page.figurePng(name.name, size.width, size.height);
      if (png) download(`${stem()}-${name.name}.png`, new Uint8Array(png), "image/png");
      else say(state.page.exportError(), true);
      state.dirty = true;
    });
    $("save-view").addEventListener("click", () => {
      const size = figureSize();
      if (!size) return;
      const png = state.page.viewPng(size.width, size.height);
      if (png) download(`${stem()}-view.png`, new Uint8Array(png), "image/png");
      else say(state.page.exportError(), true);
      state.dirty = true;
    });
  }

  // ---- start -------------------------------------------------------------------------

  async function start() {
    const module = await createRigidlab();
    const page = new module.Page();
    state.page = page;
    const why = page.attach("#canvas");
    $("loading").hidden = true;
    $("main").hidden = false;
    if (why) say(`The scene cannot be drawn here: ${why}`, true);
    state.labs = JSON.parse(page.labs());
    const pick = $("lab");
    for (const lab of state.labs) pick.add(new Option(`${lab.name}: ${lab.title}`, lab.name));
    pick.disabled = false;
    pick.addEventListener("change", () => {
      openLab(pick.value, []);
      setPlaying(false);
    });
    $("textbook").addEventListener("click", () => {
      state.page.reset();
      clearRefusals();
      changed();
    });
    bindView();
    bindExports();
    const params = new URLSearchParams(location.search);
    openLab(params.get("lab") || state.labs[0].name, addressInputs(params));
    window.addEventListener("popstate", () => {
      const p = new URLSearchParams(location.search);
      openLab(p.get("lab") || state.labs[0].name, addressInputs(p));
    });
    window.rigidlab = state;  // for the tests and the curious: the page's state
    requestAnimationFrame(frame);
  }

  start().catch((e) => {
    $("loading").textContent = `rigidlab could not start in this browser: ${e.message || e}`;
    $("loading").classList.add("error");
  });
})();
