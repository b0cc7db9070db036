// Class, parameter and port descriptions as the page shows them: the inline Markdown the
// module reference (docs/modules.md) renders from the same texts, ``code`` and `code` as
// <code>, **strong** as <strong> and *emphasis* as <em>, never the raw marks; tooltips and
// search get the bare words.

const CODE = /(``[^`]+``|`[^`]+`)/;
// **strong** and *emphasis*: the marks hug the words they enclose (as in Markdown), so
// "2 * 3 * 4" stays as written
const MARKS = /(\*\*(?=\S)[^*]*?\S\*\*|\*(?=[^\s*])[^*]*?[^\s*]\*)/;

/** The parts of a text: [kind, text] with kind "text", "code", "strong" or "em". */
function parts(text) {
    const out = [];
    for (const piece of String(text ?? "").split(CODE).filter(Boolean)) {
        const code = piece.match(/^``([^`]+)``$|^`([^`]+)`$/);
        if (code) { out.push(["code", code[1] ?? code[2]]); continue; }
        for (const bit of piece.split(MARKS).filter(Boolean)) {
            if (/^\*\*.+\*\*$/s.test(bit) && MARKS.test(bit)) out.push(["strong", bit.slice(2, -2)]);
            else if (/^\*.+\*$/s.test(bit) && MARKS.test(bit)) out.push(["em", bit.slice(1, -1)]);
            else out.push(["text", bit]);
        }
    }
    return out;
}

/** A description's text as nodes, its marks made elements. */
export function describe(text) {
    return parts(text).map(([kind, words]) => {
        if (kind === "text") return document.createTextNode(words);
        const e = document.createElement(kind);
        e.textContent = words;
        return e;
    });
}

/** A description as plain text (tooltips, search): its words without the marks. */
export function plainText(text) {
    return parts(text).map(([, words]) => words).join("");
}

/** An element of class ``cls`` holding the description, its marks made elements. */
export function descriptionElement(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    e.append(...describe(text));
    return e;
}
