// The system inspector: the kernel's figures and the UI's own, and the profiling and
// start-up windows.
import { openProfiling, openStartup } from "./run-windows.js";
import { STATE_TEXT } from "./controls.js";
const ms = (s) => (typeof s === "number" ? (s * 1000).toFixed(2) + " ms" : "-");
const pct = (f) => (typeof f === "number" ? (f * 100).toFixed(1) + " %" : "-");
const num = (v, d = 1) => (typeof v === "number" ? v.toFixed(d) : v ?? "-");
// The numerical libraries' threads: limited while the run is in real time.
const threadPools = (p) => {
    if (!p) return "-";
    if (p.error) return p.error;
    const now = (p.pools ?? []).map((x) => `${x.library} ${x.threads}`).join(", ") || "none loaded";
    return p.limit ? `${now} (${p.limit} in real time)` : `${now} (not limited)`;
};

/** The process's CPU time as a share of all cores, saying so, and in busy cores. */
function cpuUsage(s) {
    if (typeof s.cpu_usage !== "number") return "-";
    if (typeof s.cpu_cores !== "number") return pct(s.cpu_usage);
    const busy = s.cpu_usage * s.cpu_cores;
    return `${pct(s.cpu_usage)} of ${s.cpu_cores} ${s.cpu_cores === 1 ? "core" : "cores"} (${busy.toFixed(2)} busy)`;
}

const FIELDS = [
    ["System", [
        ["file", "file", (s) => s.file ?? "-"],
        ["state", "state", (s) => STATE_TEXT[s.state] ?? s.state ?? "-"],
        ["tick", "tick", (s) => (typeof s.stop_tick === "number" && s.stop_tick > 0 ? `${s.tick} / ${s.stop_tick}` : String(s.tick ?? "-"))],
        ["progress", "progress", (s) => (typeof s.stop_tick === "number" && s.stop_tick > 0 ? pct(Math.min(1, s.tick / s.stop_tick)) : "-")],
        ["time", "time", (s) => (typeof s.time === "number" ? s.time.toFixed(3) + " s" : "-")],
        ["elapsed", "elapsed", (s) => (typeof s.elapsed === "number" ? s.elapsed.toFixed(1) + " s" : "-")],
    ]],
    ["Timing", [
        ["ticks_per_second", "ticks/s", (s) => num(s.ticks_per_second, 1)],
        ["ticks_per_second_mean", "ticks/s (run mean)", (s) => num(s.ticks_per_second_mean, 1)],
        ["tick_duration", "tick duration", (s) => ms(s.tick_duration)],
        ["actual_tick_duration_mean", "actual duration (1 s mean)", (s) => ms(s.actual_tick_duration_mean)],
        ["actual_tick_duration", "actual duration (last tick)", (s) => ms(s.actual_tick_duration)],
        ["lag", "lag", (s) => ms(s.lag)],
        ["lag_max", "lag max", (s) => ms(s.lag_max)],
        ["lag_p99", "lag 99%", (s) => ms(s.lag_p99)],
        ["resyncs", "resyncs", (s) => String(s.resyncs ?? "-")],
    ]],
    ["CPU", [
        ["cpu_usage", "usage", cpuUsage],
        ["idle", "idle time", (s) => pct(s.idle)],
    ]],
    ["Priority", [
        ["priority_tick", "tick thread", (s) => (s.priority ? s.priority.tick_thread ?? "-" : "normal (not asked for)")],
        ["priority_cpus", "cores", (s) => (s.priority?.cpus ? s.priority.cpus.join(", ") : "any")],
        ["priority_memory", "memory locked", (s) => (s.priority?.memory_locked ? "yes" : "no")],
        ["priority_refused", "refused", (s) => (s.priority?.refused?.length ? s.priority.refused.join(" | ") : "nothing")],
        ["thread_pools", "math threads", (s) => threadPools(s.thread_pools)],
    ]],
    ["Web UI", [
        ["ui_updates", "updates/s", (s, ui) => num(ui.updatesPerSecond, 1)],
        ["ui_rtt", "round trip", (s, ui) => (ui.rtt === null ? "-" : ui.rtt.toFixed(1) + " ms")],
        ["ui_lag", "data lag", (s, ui) => (ui.lagTicks === null ? "-" : `${ui.lagTicks} ticks (${(ui.lagSeconds * 1000).toFixed(0)} ms)`)],
        ["ui_connection", "connection", (s, ui) => (ui.connected ? "connected" : "disconnected")],
    ]],
];

export class SystemInspector {
    constructor(el, notify = () => { }) {
        this.el = el;
        this.values = {};
        const title = document.createElement("div");
        title.className = "pane-title";
        title.textContent = "System";
        el.appendChild(title);
        const table = document.createElement("table");
        table.className = "inspector-table";
        for (const [section, fields] of FIELDS) {
            const head = table.insertRow();
            const th = document.createElement("th");
            th.colSpan = 2;
            th.textContent = section;
            head.appendChild(th);
            for (const [key, label] of fields) {
                const tr = table.insertRow();
                tr.insertCell().textContent = label;
                const td = tr.insertCell();
                td.id = "sys-" + key;
                td.className = "value";
                this.values[key] = td;
            }
        }
        el.appendChild(table);
        const tools = document.createElement("div");
        tools.className = "inspector-tools";
        for (const [id, text, title, open] of [["open-profiling", "Profiling", "per-module time, most time first", openProfiling],
            ["open-startup", "Start-up", "the time of each build step", openStartup]]) {
            const b = document.createElement("button");
            b.className = "tool small";
            b.id = id;
            b.textContent = text;
            b.title = title;
            b.addEventListener("click", () => open(notify));
            tools.appendChild(b);
        }
        el.appendChild(tools);
        this.status = {};
        this.ui = { updatesPerSecond: 0, rtt: null, lagTicks: null, lagSeconds: 0, connected: false };
    }

    show(status = this.status, ui = this.ui) {
        this.status = status;
        this.ui = ui;
        for (const [, fields] of FIELDS) {
            for (const [key, , fmt] of fields) this.values[key].textContent = fmt(status, ui);
        }
    }
}
