// A Web Worker that lays out a graph with elkjs away from the page's thread (a group of
// thousands of boxes takes elkjs seconds). Message in: an elkjs graph; out: {graph} laid
// out, or {error}.
importScripts("/static/vendor/elkjs/elk.bundled.js");
const elk = new self.ELK();     // elkjs's own in-thread worker; this thread is the worker
self.onmessage = async (e) => {
    try {
        self.postMessage({ graph: await elk.layout(e.data) });
    } catch (err) {
        self.postMessage({ error: String(err?.message || err) });
    }
};
