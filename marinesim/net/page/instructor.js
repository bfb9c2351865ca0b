/* marinesim instructor page.
 *
 * Talks to `marinesim serve` over one WebSocket (JSON, see the serve protocol): sends "hello", then actions and
 * controls; receives "welcome", "state" (several a second) and "error". Chart coordinates are metres north/east of
 * the start; headings are compass degrees clockwise from north; rate of turn and rudder are positive to starboard.
 * The other bodies (state.others) are drawn at the chart's scale, which follows own-ship, and listed with own-ship's
 * range, bearing, CPA and TCPA to each as the server's record gives them.
 * Every string from the server reaches the DOM through textContent (never innerHTML).
 */
(function () {
  "use strict";

  const TRACK_STEP_S = 5;          // one track point per 5 s of exercise time
  const STRIP_WINDOW_S = 600;      // strip charts show the last 10 min of exercise time
  const STRIP_STEP_S = 0.5;        // at most one strip sample per 0.5 s of exercise time
  const JOURNAL_LINES = 50;
  const STALE_MS = 2500;           // connected but no state for this long: "no data"
  const BACKOFF_MIN_MS = 500;
  const BACKOFF_MAX_MS = 10000;
  const MIN_SPAN_M = 800;          // the chart never zooms in closer than this across
  const NM = 1852;                 // metres per nautical mile
  const VECTOR_S = 360;            // another ship's vector: where she will be in 6 minutes, as radars draw it
  const EDGE_PX = 12;              // a body closer than this to the chart's edge, or beyond it, is marked at the edge
  const MARK_PX = 22;              // ... this far inside the edge (its ring inside the chart)
  const OTHER_COLOUR = "#8fd0c0";
  const DANGER_COLOUR = "#e2574c";
  const NEAREST_COLOUR = "#eef4fa";

  const token = new URLSearchParams(window.location.search).get("token") || "";

  const $ = (id) => document.getElementById(id);

  /** Create an element with an optional class and text (text set with textContent). */
  function el(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined && text !== null) e.textContent = String(text);
    return e;
  }

  // ---------------------------------------------------------------- state of the page
  const model = {
    scenario: null,
    criteria: [],          // welcome.scenario.criteria
    history: [],           // per criterion: {t: [], v: []}
    strips: [],            // per criterion: uPlot instance or null
    track: [],             // [[t, north_m, east_m], ...]
    lastTrackT: -Infinity,
    state: null,           // last state message
    lastStateWall: 0,      // performance.now() of the last state
    eventTimes: new Map(), // event index -> t it happened (from journal "event" entries)
    stations: new Set(),
    triggerSent: new Map(), // event index -> performance.now() when "trigger" was sent
    scaleTouched: 0,       // performance.now() of the instructor's last scale change
    alarmsKey: "",
    lagKey: "",
    others: [],            // state.others: the other bodies
    othersKey: "",         // their names and kinds, as the table's rows were built
  };

  // ---------------------------------------------------------------- formatting
  function isNum(v) {
    return typeof v === "number" && Number.isFinite(v);
  }

  /** Exercise time t (s) as hh:mm:ss. */
  function clock(t) {
    if (!isNum(t)) return "--:--:--";
    const sign = t < 0 ? "-" : "";
    const s = Math.floor(Math.abs(t));
    const p = (n) => String(n).padStart(2, "0");
    return sign + p(Math.floor(s / 3600)) + ":" + p(Math.floor(s / 60) % 60) + ":" + p(s % 60);
  }

  function fixed(v, digits) {
    return isNum(v) ? v.toFixed(digits) : "–";
  }

  /** A measured value with a sensible number of decimals for its size. */
  function smart(v) {
    if (!isNum(v)) return "–";
    const a = Math.abs(v);
    if (a >= 100) return v.toFixed(0);
    if (a >= 10) return v.toFixed(1);
    return v.toFixed(2);
  }

  /** Compass degrees as 000°. */
  function compass(v) {
    if (!isNum(v)) return "–";
    let d = Math.round(((v % 360) + 360) % 360);
    if (d === 360) d = 0;
    return String(d).padStart(3, "0") + "°";
  }

  /** Seconds as [-]m:ss. */
  function minSec(v) {
    if (!isNum(v)) return "–";
    const total = Math.round(Math.abs(v));
    return (v < 0 && total > 0 ? "-" : "") + Math.floor(total / 60) + ":" + String(total % 60).padStart(2, "0");
  }

  /** A signed starboard-positive quantity as "12 S" / "12 P" / "0". */
  function side(v, digits, unit) {
    if (!isNum(v)) return "–";
    const mag = Math.abs(v).toFixed(digits);
    if (Number(mag) === 0) return mag + unit;
    return mag + unit + (v > 0 ? " S" : " P");
  }

  /** "1.50" -> "1.5", "2.00" -> "2". */
  function trimZeros(txt) {
    return txt.indexOf(".") < 0 ? txt : txt.replace(/0+$/, "").replace(/\.$/, "");
  }

  function setText(id, text) {
    const e = $(id);
    if (e.textContent !== text) e.textContent = text;
  }

  function valueText(v) {
    if (v === null || v === undefined) return "–";
    if (typeof v === "number") return Number.isInteger(v) ? String(v) : trimZeros(smart(v));
    if (typeof v === "object") return JSON.stringify(v);
    return String(v);
  }

  // ---------------------------------------------------------------- connection
  let ws = null;
  let backoff = BACKOFF_MIN_MS;
  let retryAt = 0;

  function connect() {
    retryAt = 0;
    setConnection("connecting");
    const proto = window.location.protocol === "https:" ? "wss:" : "ws:";
    const url = proto + "//" + window.location.host + "/ws?token=" + encodeURIComponent(token);
    let sock;
    try {
      sock = new WebSocket(url);
    } catch (err) {
      scheduleReconnect();
      return;
    }
    ws = sock;
    sock.onopen = function () {
      if (ws !== sock) return;
      backoff = BACKOFF_MIN_MS;
      sock.send(JSON.stringify({type: "hello", role: "instructor", token: token}));
      document.body.dataset.connected = "yes";
      document.body.classList.remove("offline");
      model.lastStateWall = performance.now();
      setConnection("up");
    };
    sock.onmessage = function (ev) {
      if (ws !== sock) return;
      let msg;
      try {
        msg = JSON.parse(ev.data);
      } catch (err) {
        showError("unreadable message from the server", true);
        return;
      }
      handle(msg);
    };
    sock.onclose = function () {
      if (ws !== sock) return;
      ws = null;
      document.body.dataset.connected = "no";
      document.body.classList.add("offline");
      scheduleReconnect();
    };
    sock.onerror = function () { /* a close event follows */ };
  }

  function scheduleReconnect() {
    const delay = backoff;
    backoff = Math.min(backoff * 2, BACKOFF_MAX_MS);
    retryAt = performance.now() + delay;
    setConnection("down");
    window.setTimeout(connect, delay);
  }

  function setConnection(how) {
    const c = $("connection");
    if (how === "up") {
      const s = model.state;
      const since = performance.now() - model.lastStateWall;
      if (since > STALE_MS) {
        c.textContent = "connected, no data for " + Math.round(since / 1000) + " s";
        c.className = "conn conn-stale";
      } else {
        c.textContent = s && isNum(s.t) ? "connected" : "connected, waiting";
        c.className = "conn conn-up";
      }
    } else if (how === "connecting") {
      c.textContent = "disconnected, connecting…";
      c.className = "conn conn-down";
    } else {
      const left = Math.max(0, Math.ceil((retryAt - performance.now()) / 1000));
      c.textContent = "disconnected, retry in " + left + " s";
      c.className = "conn conn-down";
    }
  }

  window.setInterval(function () {
    if (ws && ws.readyState === WebSocket.OPEN) setConnection("up");
    else if (retryAt) setConnection("down");
  }, 500);

  /** Send a message (token added). Returns false, with a visible error, when not connected. */
  function send(msg) {
    if (!ws || ws.readyState !== WebSocket.OPEN) {
      showError("not connected: nothing was sent", true);
      return false;
    }
    const out = Object.assign({type: msg.type, token: token}, msg);
    ws.send(JSON.stringify(out));
    showError("", false);
    return true;
  }

  function sendAction(action, fields) {
    return send({type: "action", action: action, fields: fields});
  }

  function showError(text, local) {
    const e = $("error");
    if (!text) {
      e.textContent = "";
      return;
    }
    const t = model.state ? clock(model.state.t) + "  " : "";
    e.textContent = t + (local ? "" : "refused: ") + text;
    e.classList.toggle("local", !!local);
  }

  function handle(msg) {
    if (!msg || typeof msg !== "object") return;
    if (msg.type === "welcome") onWelcome(msg);
    else if (msg.type === "state") onState(msg);
    else if (msg.type === "error") {
      showError(String(msg.message || "error"), false);
      model.triggerSent.clear();    // a refused trigger: offer the button again at once
      if (model.state) updateEvents(model.state);
    }
  }

  // ---------------------------------------------------------------- welcome
  function onWelcome(msg) {
    const sc = msg.scenario && typeof msg.scenario === "object" ? msg.scenario : {};
    const crit = Array.isArray(sc.criteria) ? sc.criteria : [];
    const same = model.scenario && model.scenario.name === sc.name && model.criteria.length === crit.length
      && model.state && isNum(msg.t) && msg.t >= model.state.t - 1;
    model.scenario = sc;

    const title = String(sc.title || sc.name || "marinesim");
    $("title").textContent = title;
    document.title = "Instructor · " + title;
    const obj = $("objectives");
    obj.replaceChildren();
    for (const o of Array.isArray(sc.objectives) ? sc.objectives : []) obj.appendChild(el("li", "", o));
    const briefing = $("briefing");
    briefing.textContent = sc.briefing ? String(sc.briefing) : obj.children.length ? "" : "no briefing";
    briefing.classList.toggle("empty", !sc.briefing);

    buildCriteria(crit, same);
    buildEvents(Array.isArray(sc.events) ? sc.events : []);
    fillChoices("fault-select", "faults-box", Array.isArray(sc.faults) ? sc.faults : []);
    fillChoices("drive-ship", "drive-box", Array.isArray(sc.driven) ? sc.driven : []);

    model.track = [];
    model.lastTrackT = -Infinity;
    for (const p of Array.isArray(msg.track) ? msg.track : []) {
      if (Array.isArray(p) && p.length >= 3 && isNum(p[0]) && isNum(p[1]) && isNum(p[2])) {
        model.track.push([p[0], p[1], p[2]]);
        model.lastTrackT = p[0];
      }
    }

    for (const s of Array.isArray(sc.stations) ? sc.stations : []) addStation(s);
    model.eventTimes.clear();
    $("journal").replaceChildren();
    addJournal(Array.isArray(msg.journal) ? msg.journal : []);
    if (!model.state || !same) $("clock").textContent = clock(msg.t);
    $("duration").textContent = isNum(sc.duration_s) ? "of " + clock(sc.duration_s) : "";
    model.alarmsKey = "";
    scheduleDraw();
  }

  // ---------------------------------------------------------------- criteria
  let stripLo = 0;
  let stripHi = STRIP_WINDOW_S;

  function buildCriteria(crit, keepHistory) {
    for (const u of model.strips) if (u) u.destroy();
    const body = $("criteria");
    body.replaceChildren();
    model.criteria = crit;
    model.strips = [];
    if (!keepHistory) model.history = crit.map(() => ({t: [], v: []}));
    crit.forEach(function (c, i) {
      const tr = el("tr");
      tr.id = "criterion-" + i;
      const unit = c.unit ? " " + c.unit : "";
      tr.appendChild(el("td", "crit-name", c.name));
      const val = el("td", "num crit-value val-settling", "–");
      val.id = "criterion-value-" + i;
      tr.appendChild(val);
      tr.appendChild(el("td", "num crit-limit", isNum(c.limit) ? smart(c.limit) + unit : "–"));
      const lvl = el("td");
      const badge = el("span", "level level-settling", "settling");
      badge.id = "criterion-level-" + i;
      lvl.appendChild(badge);
      tr.appendChild(lvl);
      const strip = el("td", "strip");
      tr.appendChild(strip);
      body.appendChild(tr);
      model.strips.push(makeStrip(strip, c, i));
    });
    if (crit.length === 0) {
      const tr = el("tr");
      const td = el("td", "empty", "no criteria in this scenario");
      td.colSpan = 5;
      tr.appendChild(td);
      body.appendChild(tr);
    }
  }

  function makeStrip(cell, c, i) {
    if (typeof window.uPlot !== "function") return null;
    const limit = isNum(c.limit) ? c.limit : null;
    const caution = limit !== null && isNum(c.caution) ? limit * c.caution : null;
    const opts = {
      width: 204,
      height: 40,
      legend: {show: false},
      cursor: {show: false},
      select: {show: false},
      padding: [4, 2, 4, 2],
      scales: {
        x: {time: false, range: () => [stripLo, stripHi]},
        y: {range: (u, lo, hi) => yRange(lo, hi, limit)},
      },
      axes: [{show: false}, {show: false}],
      series: [{}, {stroke: "#a9c7e4", width: 1.5, points: {show: false}, spanGaps: false}],
      hooks: {draw: [(u) => drawLimits(u, limit, caution)]},
    };
    const h = model.history[i];
    return new window.uPlot(opts, [h.t.slice(), h.v.slice()], cell);
  }

  function yRange(lo, hi, limit) {
    let a = isNum(lo) ? lo : 0;
    let b = isNum(hi) ? hi : 0;
    if (limit !== null) {
      a = Math.min(a, limit, 0);
      b = Math.max(b, limit);
    } else {
      a = Math.min(a, 0);
    }
    if (b - a <= 0) b = a + 1;
    const pad = 0.1 * (b - a);
    return [a < 0 ? a - pad : a, b + pad];
  }

  function drawLimits(u, limit, caution) {
    const ctx = u.ctx;
    const left = u.bbox.left;
    const right = u.bbox.left + u.bbox.width;
    const line = function (v, colour, dash) {
      const y = Math.round(u.valToPos(v, "y", true)) + 0.5;
      ctx.save();
      ctx.strokeStyle = colour;
      ctx.lineWidth = window.devicePixelRatio || 1;
      ctx.setLineDash(dash.map((d) => d * (window.devicePixelRatio || 1)));
      ctx.beginPath();
      ctx.moveTo(left, y);
      ctx.lineTo(right, y);
      ctx.stroke();
      ctx.restore();
    };
    if (caution !== null) line(caution, "rgba(224,165,58,0.7)", [2, 3]);
    if (limit !== null) line(limit, "#e2574c", [6, 3]);
  }

  function updateCriteria(s) {
    const list = Array.isArray(s.criteria) ? s.criteria : [];
    model.criteria.forEach(function (c, i) {
      const cur = list[i] || {value: null, level: "settling"};
      const level = ["settling", "ok", "caution", "exceeded"].includes(cur.level) ? cur.level : "settling";
      const v = isNum(cur.value) ? cur.value : null;
      const val = $("criterion-value-" + i);
      const txt = v === null ? "–" : smart(v) + (c.unit ? " " + c.unit : "");
      if (val.textContent !== txt) val.textContent = txt;
      val.className = "num crit-value val-" + level;
      const badge = $("criterion-level-" + i);
      if (badge.textContent !== level) badge.textContent = level;
      badge.className = "level level-" + level;
      const h = model.history[i];
      if (!h || !isNum(s.t)) return;
      const last = h.t.length ? h.t[h.t.length - 1] : -Infinity;
      if (s.t < last) {           // exercise time went back: start the strip again
        h.t.length = 0;
        h.v.length = 0;
      } else if (s.t - last < STRIP_STEP_S) {
        return;
      }
      h.t.push(s.t);
      h.v.push(v);
      let cut = 0;
      while (cut < h.t.length && h.t[cut] < s.t - STRIP_WINDOW_S) cut++;
      if (cut > 0) {
        h.t.splice(0, cut);
        h.v.splice(0, cut);
      }
    });
  }

  function drawStrips() {
    if (!model.state || !isNum(model.state.t)) return;
    stripHi = Math.max(model.state.t, STRIP_WINDOW_S);
    stripLo = stripHi - STRIP_WINDOW_S;
    model.strips.forEach(function (u, i) {
      if (u) u.setData([model.history[i].t, model.history[i].v]);
    });
  }

  // ---------------------------------------------------------------- events
  function buildEvents(events) {
    const ul = $("events");
    ul.replaceChildren();
    model.triggerSent.clear();
    if (events.length === 0) ul.appendChild(el("li", "empty", "no scripted events"));
    for (const ev of events) {
      const li = el("li", "event ev-done");
      li.id = "event-" + ev.index;
      li.dataset.index = String(ev.index);
      if (ev.message) li.title = "message: " + String(ev.message);
      li.appendChild(el("span", "ev-index", ev.index));
      const mid = el("div");
      mid.appendChild(el("div", "ev-what", ev.what));
      mid.appendChild(el("div", "ev-trigger", ev.trigger));
      li.appendChild(mid);
      const right = el("div", "ev-right");
      const status = el("span", "ev-status", "");
      const btn = el("button", "", "trigger now");
      btn.type = "button";
      btn.id = "trigger-" + ev.index;
      btn.hidden = true;
      btn.addEventListener("click", function () {
        const index = Number(ev.index);
        if (sendAction("trigger", {index: index})) {
          model.triggerSent.set(index, performance.now());
          btn.disabled = true;
          btn.textContent = "sent…";
        }
      });
      right.appendChild(status);
      right.appendChild(btn);
      li.appendChild(right);
      ul.appendChild(li);
    }
  }

  function updateEvents(s) {
    const pending = new Set((Array.isArray(s.pending) ? s.pending : []).map(Number));
    for (const li of $("events").children) {
      if (li.dataset.index === undefined) continue;
      const index = Number(li.dataset.index);
      const btn = li.querySelector("button");
      const status = li.querySelector(".ev-status");
      const isPending = pending.has(index);
      li.className = "event " + (isPending ? "ev-pending" : "ev-done");
      let text;
      if (isPending) {
        text = "";
        const sent = model.triggerSent.get(index);
        if (sent === undefined || performance.now() - sent > 3000) {
          model.triggerSent.delete(index);
          btn.disabled = !!s.ended;
          btn.textContent = "trigger now";
        }
      } else {
        model.triggerSent.delete(index);
        const at = model.eventTimes.get(index);
        text = at !== undefined ? "at " + clock(at) : "not pending";
      }
      btn.hidden = !isPending;
      if (status.textContent !== text) status.textContent = text;
    }
  }

  // ---------------------------------------------------------------- alarms
  function updateAlarms(s) {
    const alarms = Array.isArray(s.alarms) ? s.alarms : [];
    const key = JSON.stringify(alarms);
    if (key === model.alarmsKey) return;
    model.alarmsKey = key;
    const units = new Map(model.criteria.map((c) => [c.name, c.unit ? " " + c.unit : ""]));
    const sorted = alarms.slice().sort(function (a, b) {
      const ua = a.acknowledged_s === null || a.acknowledged_s === undefined ? 0 : 1;
      const ub = b.acknowledged_s === null || b.acknowledged_s === undefined ? 0 : 1;
      return ua - ub || (b.raised_s || 0) - (a.raised_s || 0);
    });
    const ul = $("alarms");
    ul.replaceChildren();
    let unacked = 0;
    sorted.forEach(function (a) {
      const acked = isNum(a.acknowledged_s);
      const cleared = isNum(a.cleared_s);
      if (!acked) unacked++;
      const li = el("li", "alarm " + (!acked ? "alarm-unack" : cleared ? "alarm-cleared" : "alarm-ack"));
      const unit = units.get(a.criterion) || "";
      li.appendChild(el("span", "t", clock(a.raised_s)));
      li.appendChild(el("span", "alarm-name", a.criterion));
      li.appendChild(el("span", "alarm-vals", smart(a.value) + unit + " > " + smart(a.limit) + unit));
      const parts = [acked ? "acknowledged at " + clock(a.acknowledged_s) : "NOT ACKNOWLEDGED"];
      parts.push(cleared ? "cleared at " + clock(a.cleared_s) : "active");
      li.appendChild(el("span", "alarm-state", parts.join(" · ")));
      ul.appendChild(li);
    });
    if (sorted.length === 0) ul.appendChild(el("li", "empty", "no alarms"));
    $("alarm-count").textContent = unacked ? unacked + " not acknowledged" : "";
  }

  // ---------------------------------------------------------------- journal
  const KIND_LABEL = {
    event: "event", alarm: "alarm", cleared: "cleared", acknowledged: "ack", action: "instructor",
    report: "report", freeze: "frozen", pause: "frozen", resume: "resumed", scale: "scale", time_scale: "scale",
    join: "joined", leave: "left", end: "end",
  };

  /** Words for the fields of a sea change, a weather change and an order: [before, after] the value. */
  const FIELD_WORDS = {
    hs_factor: ["Hs ×", ""], tp_factor: ["Tp ×", ""], turn_waves_deg: ["waves turned ", "°"],
    visibility_m: ["visibility ", " m"], cloud_cover_oktas: ["cloud ", " oktas"],
    wind_speed_m_s: ["wind ", " m/s"], rain_mm_h: ["rain ", " mm/h"], hours: ["clock +", " h"],
    fault: ["fault injected: ", ""], engine: ["engine ", ""], speed_kn: ["speed ", " kn"],
    heading_deg: ["heading ", ""], course_deg: ["course ", ""], rudder_deg: ["rudder ", ""],
    autopilot: ["autopilot ", ""], set_north_m: ["set north ", " m"], set_east_m: ["set east ", " m"],
    ramp_s: ["over ", " s"],
  };

  /** Entry fields, with an action's nested "fields" (if the server nests them) lifted up. */
  function flat(e) {
    const out = Object.assign({}, e);
    if (e.fields && typeof e.fields === "object") {
      delete out.fields;
      Object.assign(out, e.fields);
    }
    return out;
  }

  /** "key: value" for the fields not already put into words. */
  function rest(e, used) {
    const skip = new Set(["t", "kind"].concat(used));
    const parts = [];
    for (const k of Object.keys(e)) {
      if (!skip.has(k)) parts.push(k + ": " + valueText(e[k]));
    }
    return parts.length ? " (" + parts.join(", ") + ")" : "";
  }

  function pick(e, keys) {
    for (const k of keys) if (e[k] !== undefined && e[k] !== null) return [k, e[k]];
    return [null, undefined];
  }

  function who(e) {
    const [k, v] = pick(e, ["station", "name", "who"]);
    return [k, v === undefined ? "a station" : String(v)];
  }

  /** The fields of FIELD_WORDS in e, in words, and the keys used. */
  function fieldWords(e) {
    const parts = [];
    const used = [];
    for (const k of Object.keys(FIELD_WORDS)) {
      if (e[k] === undefined) continue;
      let v = valueText(e[k]);
      if (k === "autopilot") v = e[k] ? "on" : "off";
      else if (k === "engine") v = String(e[k]).replace(/_/g, " ");
      else if (k === "rudder_deg") v = side(e[k], 0, "°");
      else if ((k === "heading_deg" || k === "course_deg") && isNum(e[k])) v = compass(e[k]);
      parts.push(FIELD_WORDS[k][0] + v + FIELD_WORDS[k][1]);
      used.push(k);
    }
    return [parts.join(", "), used];
  }

  /** [label, words, style] of an "action" entry. */
  function describeAction(e) {
    const a = String(e.action || "");
    if (a === "message") {
      const to = e.to === undefined || e.to === "all" ? "all stations" : String(e.to);
      const words = "to " + to + ": “" + String(e.text || "") + "”";
      return ["message", words + rest(e, ["action", "text", "to"]), "action"];
    }
    if (a === "report") {   // a trainee's report to the instructor, journaled as an action
      const [k, s] = who(e);
      return ["report", s + ": " + String(e.text || "") + rest(e, ["action", k, "text"]), "report"];
    }
    if (a === "acknowledge") {
      const [k, s] = who(e);
      return ["ack", "alarms acknowledged" + (k ? " at " + s : "") + rest(e, ["action", k]), "acknowledged"];
    }
    if (a === "trigger") {
      return ["trigger", "event " + valueText(e.index) + " triggered now" + rest(e, ["action", "index"]), "action"];
    }
    const [words, used] = fieldWords(e);
    const label = {change: "sea", weather: "weather", order: "order"}[a] || a || "action";
    const ship = a === "order" && typeof e.vessel === "string" ? e.vessel + ": " : "";
    const head = a === "change" ? "sea change: " : a === "weather" ? "weather: " : a === "order" ? ship : a + ": ";
    return [label, head + words + rest(e, ["action", "vessel"].concat(used)), "action"];
  }

  /** Readable [label, words, style] for one journal entry. */
  function describe(raw) {
    const e = flat(raw);
    const kind = String(e.kind || "");
    const label = KIND_LABEL[kind] || kind || "?";
    switch (kind) {
      case "event": {
        const early = e.early ? ", triggered early" : "";
        return [label, "#" + valueText(e.index) + " " + String(e.what || "") + early
          + rest(e, ["index", "what", "early"]), kind];
      }
      case "alarm": {
        const words = String(e.criterion || "") + " " + smart(e.value) + " over limit " + smart(e.limit);
        return [label, words + rest(e, ["criterion", "value", "limit", "raised_s"]), kind];
      }
      case "cleared": {
        const v = isNum(e.value) ? " (" + smart(e.value) + ")" : "";
        return [label, String(e.criterion || "") + " back within its limit" + v
          + rest(e, ["criterion", "value", "cleared_s"]), kind];
      }
      case "acknowledged": {
        const [kc, c] = pick(e, ["criteria", "criterion"]);
        const names = Array.isArray(c) ? c.map(String).join(", ") : c === undefined ? "alarm" : String(c);
        const [ks, s] = pick(e, ["station", "by"]);
        const by = ks ? " at " + String(s) : "";
        const d = Array.isArray(e.delays_s) && e.delays_s.length && e.delays_s.every(isNum)
          ? " after " + e.delays_s.map((x) => x.toFixed(0)).join(", ") + " s" : "";
        return [label, names + " acknowledged" + by + d + rest(e, [kc, ks, "delays_s", "acknowledged_s"]), kind];
      }
      case "action":
        return describeAction(e);
      case "report": {
        const [k, s] = who(e);
        return [label, s + ": " + String(e.text || "") + rest(e, [k, "text"]), kind];
      }
      case "freeze":
      case "pause":
        return [label, "exercise frozen" + rest(e, []), "freeze"];
      case "resume":
        return [label, "exercise resumed" + rest(e, []), kind];
      case "scale":
      case "time_scale": {
        const [k, v] = pick(e, ["scale", "value"]);
        return [label, "time scale " + valueText(v) + "×" + rest(e, [k]), "scale"];
      }
      case "join":
      case "leave": {
        const [k, s] = who(e);
        return [label, s + (kind === "join" ? " joined" : " left") + rest(e, [k]), kind];
      }
      case "end":
        return [label, "exercise ended" + rest(e, []), kind];
      default:
        return [label, rest(e, []).replace(/^ \(|\)$/g, ""), "other"];
    }
  }

  function addJournal(entries) {
    const ul = $("journal");
    for (const e of entries) {
      if (!e || typeof e !== "object") continue;
      if (e.kind === "event" && e.index !== undefined && isNum(e.t)) model.eventTimes.set(Number(e.index), e.t);
      if (e.kind === "join") {
        const [k, s] = who(e);
        if (k) addStation(s);
      }
      const [label, words, style] = describe(e);
      const li = el("li", "j-" + style);
      li.appendChild(el("span", "t", clock(e.t)));
      const text = el("span", "j-text");
      text.appendChild(el("span", "j-kind", label));
      text.appendChild(document.createTextNode(words));
      li.appendChild(text);
      ul.insertBefore(li, ul.firstChild);
    }
    while (ul.children.length > JOURNAL_LINES) ul.removeChild(ul.lastChild);
  }

  // ---------------------------------------------------------------- stations (message recipients)
  function addStation(name) {
    if (name === undefined || name === null || name === "" || name === "all") return;
    name = String(name);
    if (model.stations.has(name)) return;
    model.stations.add(name);
    const sel = $("message-to");
    const keep = sel.value;
    sel.replaceChildren(el("option", "", "all"));
    sel.firstChild.value = "all";
    for (const s of Array.from(model.stations).sort()) {
      const o = el("option", "", s);
      o.value = s;
      sel.appendChild(o);
    }
    sel.value = model.stations.has(keep) ? keep : "all";
  }

  function updateStations(s) {
    if (Array.isArray(s.stations)) for (const n of s.stations) addStation(n);
    const lag = s.lag_s && typeof s.lag_s === "object" ? s.lag_s : {};
    const names = Object.keys(lag).sort();
    for (const n of names) addStation(n);
    const text = names.length ? "lag: " + names.map((n) => n + " " + fixed(lag[n], 1) + " s").join(" · ")
      : "no bridge connected";
    if (text !== model.lagKey) {
      model.lagKey = text;
      $("stations").textContent = text;
    }
  }

  // ---------------------------------------------------------------- faults, and the other ships the instructor drives
  /** The options of select ``selectId`` set to ``names``; the box ``boxId`` shown only when there are some. */
  function fillChoices(selectId, boxId, names) {
    const sel = $(selectId);
    sel.replaceChildren();
    for (const name of names) {
      const o = el("option", "", name);
      o.value = String(name);
      sel.appendChild(o);
    }
    $(boxId).hidden = names.length === 0;
  }

  function orderShip() {
    const fields = {vessel: $("drive-ship").value};
    for (const [id, key, lo, hi] of [["drive-course", "course_deg", 0, 360], ["drive-speed", "speed_kn", 0, 30]]) {
      const input = $(id);
      if (input.value === "") continue;
      const v = Number(input.value);
      if (!isNum(v) || v < lo || v > hi) {
        input.classList.add("bad");
        showError(key + ": expected " + lo + " to " + hi, true);
        return;
      }
      fields[key] = v;
    }
    if (!fields.vessel || Object.keys(fields).length === 1) {
      showError("traffic: give her a course or a speed", true);
      return;
    }
    sendAction("order", fields);
  }

  // ---------------------------------------------------------------- state
  function onState(s) {
    model.state = s;
    model.lastStateWall = performance.now();
    if (isNum(s.t)) document.body.dataset.t = String(s.t);

    $("clock").textContent = clock(s.t);
    $("time-scale").textContent = isNum(s.scale) ? s.scale + "×" : "–";
    $("frozen").hidden = !s.frozen;
    $("ended").hidden = !s.ended;
    $("freeze").disabled = !!s.frozen;
    $("resume").disabled = !s.frozen;
    updateScaleSelect(s.scale);

    const ship = s.ship && typeof s.ship === "object" ? s.ship : {};
    $("nav-heading").textContent = compass(ship.heading_deg);
    $("nav-cog").textContent = compass(ship.course_over_ground_deg);
    $("nav-sog").textContent = fixed(ship.speed_over_ground_kn, 1) + " kn";
    $("nav-rot").textContent = side(ship.rate_of_turn_deg_min, 0, "°/min");
    $("nav-rudder").textContent = side(ship.rudder_deg, 0, "°");
    $("nav-course").textContent = isNum(ship.course_deg) ? compass(ship.course_deg) : "none";
    $("nav-engine").textContent = ship.engine === undefined || ship.engine === null ? "–"
      : String(ship.engine).replace(/_/g, " ");
    $("nav-motion").textContent = fixed(ship.roll_deg, 1) + "° / " + fixed(ship.pitch_deg, 1) + "°";

    if (isNum(s.t) && isNum(ship.north_m) && isNum(ship.east_m)) {
      if (s.t < model.lastTrackT - TRACK_STEP_S) {
        model.track = [];
        model.lastTrackT = -Infinity;
      }
      if (s.t - model.lastTrackT >= TRACK_STEP_S) {
        model.track.push([s.t, ship.north_m, ship.east_m]);
        model.lastTrackT = s.t;
      }
    }

    const sea = s.sea || {};
    setText("sea-now", "now Hs " + fixed(sea.hs_m, 1) + " m · Tp " + fixed(sea.tp_s, 1) + " s · from "
      + compass(sea.from_deg));
    const w = s.weather || {};
    $("weather-visibility").placeholder = fixed(w.visibility_m, 0);
    $("weather-cloud").placeholder = fixed(w.cloud_cover_oktas, 0);
    $("weather-wind").placeholder = fixed(w.wind_speed_m_s, 1);
    $("weather-rain").placeholder = fixed(w.rain_mm_h, 1);
    $("weather-hours").placeholder = "0";

    addJournal(Array.isArray(s.journal) ? s.journal : []);
    updateCriteria(s);
    updateAlarms(s);
    updateEvents(s);
    updateStations(s);
    updateOthers(s);
    setConnection("up");
    scheduleDraw();
  }

  // ---------------------------------------------------------------- other bodies
  function updateOthers(s) {
    const list = Array.isArray(s.others) ? s.others.filter((o) => o && typeof o === "object") : [];
    model.others = list;
    const key = JSON.stringify(list.map((o) => [o.name, o.kind]));
    const body = $("others");
    if (key !== model.othersKey) {
      model.othersKey = key;
      body.replaceChildren();
      list.forEach(function (o, i) {
        const tr = el("tr", "other");
        tr.id = "other-" + i;
        tr.dataset.name = String(o.name);
        tr.appendChild(el("td", "other-name", o.name));
        tr.appendChild(el("td", "other-kind", o.kind));
        for (const what of ["range", "bearing", "cpa", "tcpa"]) {
          const td = el("td", "num", "–");
          td.id = "other-" + what + "-" + i;
          tr.appendChild(td);
        }
        const chart = el("td", "other-chart", "");
        chart.id = "other-chart-" + i;
        tr.appendChild(chart);
        body.appendChild(tr);
      });
      $("others-panel").hidden = list.length === 0;
    }
    list.forEach(function (o, i) {
      setText("other-range-" + i, isNum(o.range_m) ? fixed(o.range_m / NM, 2) : "–");
      setText("other-bearing-" + i, compass(o.bearing_deg));
      setText("other-cpa-" + i, isNum(o.cpa_m) ? fixed(o.cpa_m / NM, 2) : "–");
      setText("other-tcpa-" + i, minSec(o.tcpa_s));
      const cls = "other" + (o.danger === true ? " other-danger" : "") + (o.nearest === true ? " other-nearest" : "");
      const tr = $("other-" + i);
      if (tr.className !== cls) tr.className = cls;
    });
  }

  function updateScaleSelect(scale) {
    const sel = $("scale");
    if (!isNum(scale) || document.activeElement === sel) return;
    if (performance.now() - model.scaleTouched < 3000) return;
    const v = String(scale);
    if (!Array.from(sel.options).some((o) => o.value === v)) {
      const o = el("option", "", v + "×");
      o.value = v;
      sel.appendChild(o);
    }
    if (sel.value !== v) sel.value = v;
  }

  // ---------------------------------------------------------------- chart
  let drawPending = false;

  function scheduleDraw() {
    if (drawPending) return;
    drawPending = true;
    window.requestAnimationFrame(function () {
      drawPending = false;
      drawChart();
      drawStrips();
    });
  }

  /** The smallest of 1, 2, 5 x 10^k that is >= x. */
  function nice125(x) {
    const p = Math.pow(10, Math.floor(Math.log10(x)));
    for (const m of [1, 2, 5, 10]) if (m * p >= x) return m * p;
    return 10 * p;
  }

  /** Metres per pixel rounded up to a ladder of steps about 25% apart, so the chart zooms in steps. */
  function niceScale(x) {
    const p = Math.pow(10, Math.floor(Math.log10(x)));
    for (const m of [1, 1.25, 1.6, 2, 2.5, 3.2, 4, 5, 6.4, 8, 10]) if (m * p >= x) return m * p;
    return 10 * p;
  }

  function drawChart() {
    const canvas = $("chart");
    const rect = canvas.getBoundingClientRect();
    const w = Math.max(10, Math.floor(rect.width));
    const h = Math.max(10, Math.floor(rect.height));
    const dpr = window.devicePixelRatio || 1;
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
    }
    const ctx = canvas.getContext("2d");
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = "#0f1a24";
    ctx.fillRect(0, 0, w, h);

    const s = model.state;
    const ship = s && s.ship && isNum(s.ship.north_m) && isNum(s.ship.east_m) ? s.ship : null;
    const predicted = s && Array.isArray(s.predicted)
      ? s.predicted.filter((p) => Array.isArray(p) && isNum(p[0]) && isNum(p[1])) : [];
    const pts = model.track.map((p) => [p[1], p[2]]).concat(predicted);
    if (ship) pts.push([ship.north_m, ship.east_m]);
    if (pts.length === 0) {
      ctx.fillStyle = "#7f90a1";
      ctx.font = "16px sans-serif";
      ctx.textAlign = "center";
      ctx.fillText("waiting for the simulator…", w / 2, h / 2);
      return;
    }
    pts.push([0, 0]);   // the start
    let n0 = Infinity, n1 = -Infinity, e0 = Infinity, e1 = -Infinity;
    for (const [n, e] of pts) {
      n0 = Math.min(n0, n); n1 = Math.max(n1, n);
      e0 = Math.min(e0, e); e1 = Math.max(e1, e);
    }
    const pad = 48;
    const spanN = Math.max(n1 - n0, MIN_SPAN_M * 0.5);
    const spanE = Math.max(e1 - e0, MIN_SPAN_M * 0.5);
    const mpp = niceScale(Math.max(spanE / (w - 2 * pad), spanN / (h - 2 * pad), MIN_SPAN_M / Math.min(w, h)));
    const cn = (n0 + n1) / 2;
    const ce = (e0 + e1) / 2;
    const X = (e) => w / 2 + (e - ce) / mpp;
    const Y = (n) => h / 2 - (n - cn) / mpp;

    const useNM = w * mpp >= 4000;
    const unit = useNM ? NM : 1;
    drawGrid(ctx, w, h, mpp, cn, ce, unit, useNM);

    // start
    ctx.strokeStyle = "#7f90a1";
    ctx.lineWidth = 1.5;
    ctx.strokeRect(X(0) - 4, Y(0) - 4, 8, 8);
    ctx.fillStyle = "#7f90a1";
    ctx.font = "11px sans-serif";
    ctx.textAlign = "left";
    ctx.fillText("start", X(0) + 7, Y(0) + 4);

    // track so far
    ctx.strokeStyle = "#6fa8d8";
    ctx.lineWidth = 2;
    ctx.setLineDash([]);
    ctx.beginPath();
    model.track.forEach(function (p, i) {
      if (i === 0) ctx.moveTo(X(p[2]), Y(p[1]));
      else ctx.lineTo(X(p[2]), Y(p[1]));
    });
    if (ship && model.track.length) ctx.lineTo(X(ship.east_m), Y(ship.north_m));
    ctx.stroke();

    // predicted track: dashed, a dot each minute (points every 10 s)
    if (ship && predicted.length) {
      ctx.strokeStyle = "#d7e3ee";
      ctx.lineWidth = 1.5;
      ctx.setLineDash([7, 6]);
      ctx.beginPath();
      ctx.moveTo(X(ship.east_m), Y(ship.north_m));
      for (const p of predicted) ctx.lineTo(X(p[1]), Y(p[0]));
      ctx.stroke();
      ctx.setLineDash([]);
      ctx.fillStyle = "#d7e3ee";
      predicted.forEach(function (p, i) {
        if ((i + 1) % 6 === 0) {
          ctx.beginPath();
          ctx.arc(X(p[1]), Y(p[0]), 2.5, 0, 2 * Math.PI);
          ctx.fill();
        }
      });
    }

    const vectors = drawOthers(ctx, X, Y, w, h, mpp);
    if (ship) drawShip(ctx, X(ship.east_m), Y(ship.north_m), ship.heading_deg);
    canvas.dataset.view = JSON.stringify({centre_east_m: ce, centre_north_m: cn, m_per_px: mpp, width_px: w,
      height_px: h});

    drawScaleBar(ctx, h, mpp, unit, useNM);
    drawNorthArrow(ctx, w);
    ctx.fillStyle = "#7f90a1";
    ctx.font = "11px sans-serif";
    ctx.textAlign = "right";
    if (predicted.length) ctx.fillText("dashed: predicted 3 min (dot per minute)", w - 12, h - 12);
    if (vectors) ctx.fillText("other ships: 6 min vectors", w - 12, h - 27);
  }

  /** The other bodies at the chart's scale: a ship as a small hull outline on her heading with her 6-minute
   * vector, an FPSO or a platform as a square, a buoy as a circle, each named; red when dangerous, ringed when the
   * nearest CPA ahead. One beyond the chart's edge is marked at the edge, towards it, and said so in the table.
   * Returns whether a ship's vector was drawn. */
  function drawOthers(ctx, X, Y, w, h, mpp) {
    let vectors = false;
    model.others.forEach(function (o, i) {
      const cell = $("other-chart-" + i);
      if (!isNum(o.east_m) || !isNum(o.north_m)) {
        if (cell) setText(cell.id, "");
        return;
      }
      const x = X(o.east_m), y = Y(o.north_m);
      const inside = x >= EDGE_PX && x <= w - EDGE_PX && y >= EDGE_PX && y <= h - EDGE_PX;
      if (cell) setText(cell.id, inside ? "" : "off chart");
      const colour = o.danger === true ? DANGER_COLOUR : OTHER_COLOUR;
      ctx.save();
      ctx.strokeStyle = colour;
      ctx.fillStyle = colour;
      ctx.lineWidth = 1.5;
      ctx.setLineDash([]);
      ctx.font = "11px sans-serif";
      let at = [x, y];
      if (!inside) {
        at = drawEdgeMark(ctx, x, y, w, h);
      } else if (o.kind === "ship") {
        const vector = isNum(o.speed_kn) ? o.speed_kn * NM / 3600 * VECTOR_S / mpp : 0;
        drawOtherShip(ctx, x, y, o.heading_deg, vector);
        vectors = vectors || vector > 0;
      } else if (o.kind === "buoy") {
        ctx.beginPath();
        ctx.arc(x, y, 4.5, 0, 2 * Math.PI);
        ctx.stroke();
      } else {
        ctx.strokeRect(x - 6, y - 6, 12, 12);
      }
      if (o.nearest === true) {
        ctx.strokeStyle = NEAREST_COLOUR;
        ctx.lineWidth = 1;
        ctx.beginPath();
        ctx.arc(at[0], at[1], 17, 0, 2 * Math.PI);
        ctx.stroke();
      }
      const right = at[0] < w - 120;
      ctx.textAlign = right ? "left" : "right";
      ctx.fillText(String(o.name), at[0] + (right ? 20 : -20), at[1] + (at[1] < 20 ? 14 : 4));
      ctx.restore();
    });
    return vectors;
  }

  /** Another ship at (x, y) px heading ``heading`` (compass deg): a hull outline 22 px long and her vector,
   * ``vector`` px from her centre along her heading. */
  function drawOtherShip(ctx, x, y, heading, vector) {
    ctx.save();
    ctx.translate(x, y);
    ctx.rotate((isNum(heading) ? heading : 0) * Math.PI / 180);
    if (vector > 11) {
      ctx.beginPath();
      ctx.moveTo(0, -11);
      ctx.lineTo(0, -vector);
      ctx.stroke();
    }
    ctx.beginPath();
    ctx.moveTo(0, -11);
    ctx.quadraticCurveTo(4.5, -6, 4, -1);
    ctx.lineTo(4, 10);
    ctx.lineTo(-4, 10);
    ctx.lineTo(-4, -1);
    ctx.quadraticCurveTo(-4.5, -6, 0, -11);
    ctx.closePath();
    ctx.stroke();
    ctx.restore();
  }

  /** A triangle on the chart's edge pointing at (x, y) px beyond it, on the line from the chart's centre; returns
   * where it is drawn. */
  function drawEdgeMark(ctx, x, y, w, h) {
    const dx = x - w / 2, dy = y - h / 2;
    const reach = Math.min(Math.abs(dx) > 0 ? (w / 2 - MARK_PX) / Math.abs(dx) : Infinity,
      Math.abs(dy) > 0 ? (h / 2 - MARK_PX) / Math.abs(dy) : Infinity);
    const px = w / 2 + dx * reach, py = h / 2 + dy * reach;
    const a = Math.atan2(dy, dx);
    ctx.beginPath();
    ctx.moveTo(px + 8 * Math.cos(a), py + 8 * Math.sin(a));
    ctx.lineTo(px + 6 * Math.cos(a + 2.4), py + 6 * Math.sin(a + 2.4));
    ctx.lineTo(px + 6 * Math.cos(a - 2.4), py + 6 * Math.sin(a - 2.4));
    ctx.closePath();
    ctx.fill();
    return [px, py];
  }

  function drawGrid(ctx, w, h, mpp, cn, ce, unit, useNM) {
    const step = nice125(90 * mpp / unit) * unit;   // metres between grid lines, >= 90 px
    const eLo = ce - (w / 2) * mpp, eHi = ce + (w / 2) * mpp;
    const nLo = cn - (h / 2) * mpp, nHi = cn + (h / 2) * mpp;
    const X = (e) => w / 2 + (e - ce) / mpp;
    const Y = (n) => h / 2 - (n - cn) / mpp;
    const label = function (v, pos, neg) {
      const a = Math.abs(v) / unit;
      const txt = useNM ? (Math.round(a * 100) / 100) + " NM" : Math.round(a) + " m";
      return v === 0 ? "0" : txt + " " + (v > 0 ? pos : neg);
    };
    ctx.lineWidth = 1;
    ctx.setLineDash([]);
    ctx.font = "11px sans-serif";
    ctx.fillStyle = "#56677a";
    for (let e = Math.ceil(eLo / step) * step; e <= eHi; e += step) {
      const x = Math.round(X(e)) + 0.5;
      ctx.strokeStyle = Math.abs(e) < step / 2 ? "#2f4256" : "#1e2c3a";
      ctx.beginPath();
      ctx.moveTo(x, 0);
      ctx.lineTo(x, h);
      ctx.stroke();
      ctx.textAlign = "left";
      if (x < w - 110) ctx.fillText(label(Math.abs(e) < step / 2 ? 0 : e, "E", "W"), x + 3, 14);  // clear of N
    }
    for (let n = Math.ceil(nLo / step) * step; n <= nHi; n += step) {
      const y = Math.round(Y(n)) + 0.5;
      ctx.strokeStyle = Math.abs(n) < step / 2 ? "#2f4256" : "#1e2c3a";
      ctx.beginPath();
      ctx.moveTo(0, y);
      ctx.lineTo(w, y);
      ctx.stroke();
      ctx.textAlign = "left";
      ctx.fillText(label(Math.abs(n) < step / 2 ? 0 : n, "N", "S"), 4, y - 3);
    }
  }

  function drawShip(ctx, x, y, heading) {
    const hd = isNum(heading) ? heading : 0;
    ctx.save();
    ctx.translate(x, y);
    ctx.rotate(hd * Math.PI / 180);   // canvas y is down, so a positive angle turns clockwise, like a compass
    // heading line
    ctx.strokeStyle = "#eef4fa";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(0, -16);
    ctx.lineTo(0, -90);
    ctx.stroke();
    // hull: pointed bow up, square stern, 32 px long, 11 px wide
    ctx.beginPath();
    ctx.moveTo(0, -16);
    ctx.quadraticCurveTo(6, -9, 5.5, -2);
    ctx.lineTo(5.5, 14);
    ctx.lineTo(-5.5, 14);
    ctx.lineTo(-5.5, -2);
    ctx.quadraticCurveTo(-6, -9, 0, -16);
    ctx.closePath();
    ctx.fillStyle = "#eef4fa";
    ctx.fill();
    ctx.strokeStyle = "#0f1a24";
    ctx.lineWidth = 1;
    ctx.stroke();
    ctx.restore();
  }

  function drawScaleBar(ctx, h, mpp, unit, useNM) {
    const len = nice125(140 * mpp / unit);     // in units, about 140 px or more
    const px = len * unit / mpp;
    const x0 = 16, y0 = h - 22;
    ctx.strokeStyle = "#c9d4df";
    ctx.fillStyle = "#c9d4df";
    ctx.lineWidth = 2;
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(x0, y0 - 6);
    ctx.lineTo(x0, y0);
    ctx.lineTo(x0 + px, y0);
    ctx.lineTo(x0 + px, y0 - 6);
    ctx.stroke();
    ctx.font = "bold 12px sans-serif";
    ctx.textAlign = "center";
    ctx.fillText(useNM ? len + " NM" : len + " m", x0 + px / 2, y0 - 6);
  }

  function drawNorthArrow(ctx, w) {
    const x = w - 30, y = 44;
    ctx.fillStyle = "rgba(15,26,36,0.85)";
    ctx.fillRect(x - 20, y - 44, 40, 60);
    ctx.fillStyle = "#c9d4df";
    ctx.strokeStyle = "#c9d4df";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    ctx.moveTo(x, y - 20);
    ctx.lineTo(x + 8, y + 8);
    ctx.lineTo(x, y + 2);
    ctx.closePath();
    ctx.fill();
    ctx.beginPath();
    ctx.moveTo(x, y - 20);
    ctx.lineTo(x - 8, y + 8);
    ctx.lineTo(x, y + 2);
    ctx.closePath();
    ctx.stroke();
    ctx.font = "bold 14px sans-serif";
    ctx.textAlign = "center";
    ctx.fillText("N", x, y - 24);
  }

  window.addEventListener("resize", scheduleDraw);

  // ---------------------------------------------------------------- controls
  /** Read a number input: [ok, value]; value null when empty; shows an error naming the field when invalid. */
  function readNumber(id, what) {
    const input = $(id);
    const vs = input.validity;   // a value between the spinner's steps is fine: stepMismatch is not checked
    input.classList.remove("bad");
    if (vs.badInput || vs.rangeUnderflow || vs.rangeOverflow) {
      input.classList.add("bad");
      const lo = input.min !== "" ? " ≥ " + input.min : "";
      const hi = input.max !== "" ? " and ≤ " + input.max : "";
      showError(what + ": expected a number" + lo + hi, true);
      input.focus();
      return [false, null];
    }
    if (input.value.trim() === "") return [true, null];
    const v = Number(input.value);
    if (!Number.isFinite(v)) {
      input.classList.add("bad");
      showError(what + ": expected a number", true);
      input.focus();
      return [false, null];
    }
    return [true, v];
  }

  /** Fields from inputs [[id, key, what], ...] that hold a number; null if one is invalid. */
  function readFields(spec) {
    const fields = {};
    for (const [id, key, what] of spec) {
      const [ok, v] = readNumber(id, what);
      if (!ok) return null;
      if (v !== null) fields[key] = v;
    }
    return fields;
  }

  const SEA = [
    ["sea-hs-factor", "hs_factor", "Hs factor"], ["sea-tp-factor", "tp_factor", "Tp factor"],
    ["sea-turn-waves", "turn_waves_deg", "turn waves (deg)"], ["sea-ramp", "ramp_s", "ramp (s)"],
  ];
  const SEA_NEUTRAL = {"sea-hs-factor": "1", "sea-tp-factor": "1", "sea-turn-waves": "0"};
  const WEATHER = [
    ["weather-visibility", "visibility_m", "visibility (m)"], ["weather-cloud", "cloud_cover_oktas", "cloud (oktas)"],
    ["weather-wind", "wind_speed_m_s", "wind (m/s)"], ["weather-rain", "rain_mm_h", "rain (mm/h)"],
    ["weather-hours", "hours", "clock +hours"],
  ];

  $("sea-apply").addEventListener("click", function () {
    const fields = readFields(SEA);
    if (fields === null) return;
    if (Object.keys(fields).length === 0) {
      showError("sea: fill in at least one field", true);
      return;
    }
    // Factors apply to the present sea: put them back to "no change" so a second click does not compound.
    if (sendAction("change", fields)) for (const id of Object.keys(SEA_NEUTRAL)) $(id).value = SEA_NEUTRAL[id];
  });

  $("weather-apply").addEventListener("click", function () {
    const fields = readFields(WEATHER);
    if (fields === null) return;
    if (Object.keys(fields).length === 0) {
      showError("weather: fill in at least one field", true);
      return;
    }
    const ramp = readFields([["weather-ramp", "ramp_s", "ramp (s)"]]);
    if (ramp === null) return;
    if (sendAction("weather", Object.assign(fields, ramp))) for (const [id] of WEATHER) $(id).value = "";
  });

  function sendMessage() {
    const text = $("message-text").value.trim();
    if (!text) {
      showError("message: write some text first", true);
      $("message-text").focus();
      return;
    }
    if (sendAction("message", {text: text, to: $("message-to").value || "all"})) $("message-text").value = "";
  }

  $("message-send").addEventListener("click", sendMessage);
  $("message-text").addEventListener("keydown", function (ev) {
    if (ev.key === "Enter") {
      ev.preventDefault();
      sendMessage();
    }
  });

  $("freeze").addEventListener("click", () => send({type: "control", control: "freeze"}));
  $("resume").addEventListener("click", () => send({type: "control", control: "resume"}));
  $("scale").addEventListener("change", function () {
    model.scaleTouched = performance.now();
    send({type: "control", control: "scale", value: Number($("scale").value)});
  });
  $("drive-order").addEventListener("click", orderShip);
  $("fault-inject").addEventListener("click", function () {
    const f = $("fault-select").value;
    if (!f) {
      showError("fault: choose one first", true);
      return;
    }
    sendAction("order", {fault: f});
  });

  for (const input of document.querySelectorAll("input[type=number]")) {
    input.addEventListener("input", () => input.classList.remove("bad"));
  }

  if (!token) showError("this page's address has no ?token=…; the server will refuse the connection", true);
  connect();
  scheduleDraw();
})();
