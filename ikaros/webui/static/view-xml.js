// A view (or a list of widgets) of the editor's model tree as Ikaros XML text, for "Copy
// view as XML": the element with its attributes in their order, escaped, indented.

const escape = (text) => String(text).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;").replace(/"/g, "&quot;");

/** One element of the tree ({tag, attrs, children}) as XML; comments are kept. */
export function elementXml(n, indent = "") {
    if (n.tag === "#comment") return `${indent}<!--${n.text ?? ""}-->`;
    if (n.tag.startsWith("#")) return "";
    const attrs = Object.entries(n.attrs || {}).map(([k, v]) => ` ${k}="${escape(v)}"`).join("");
    const kids = (n.children || []).map((c) => elementXml(c, indent + "    ")).filter(Boolean);
    if (!kids.length) return `${indent}<${n.tag}${attrs} />`;
    return `${indent}<${n.tag}${attrs}>\n${kids.join("\n")}\n${indent}</${n.tag}>`;
}

/** The XML of the view that holds a widget: its <view> element, or (Ikaros 3 widgets held
 *  directly by a group) the group's <widget> elements. */
export function viewXml(parent) {
    if (parent.tag === "view") return elementXml(parent) + "\n";
    return (parent.children || []).filter((c) => c.tag === "widget").map((c) => elementXml(c)).join("\n") + "\n";
}
