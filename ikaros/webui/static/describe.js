// Class, parameter and port descriptions as the page shows them: their ``code`` and `code`
// markup becomes <code> elements (never raw backticks); tooltips get the bare words.

const CODE = /(``[^`]+``|`[^`]+`)/;

/** A description's text as nodes, code marked up. */
export function describe(text) {
    return String(text).split(CODE).filter(Boolean).map((part) => {
        const m = part.match(/^``([^`]+)``$|^`([^`]+)`$/);
        if (!m) return document.createTextNode(part);
        const code = document.createElement("code");
        code.textContent = m[1] ?? m[2];
        return code;
    });
}

/** A description as plain text (tooltips, search): the code's words without backticks. */
export function plainText(text) {
    return String(text ?? "").replace(/``([^`]+)``|`([^`]+)`/g, (_, a, b) => a ?? b);
}

/** An element of class ``cls`` holding the description, code marked up. */
export function descriptionElement(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    e.append(...describe(text));
    return e;
}
