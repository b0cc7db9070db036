// A small modal dialog of the page (the editor's and the record button's).

/** A modal dialog: title, body element, buttons [[label, fn, id?]]. Returns {el, close}. */
export function dialog(title, body, buttons) {
    const back = document.createElement("div");
    back.className = "editor-dialog-back";
    const box = document.createElement("div");
    box.className = "editor-dialog";
    const head = document.createElement("div");
    head.className = "pane-title";
    head.textContent = title;
    const foot = document.createElement("div");
    foot.className = "dialog-buttons";
    const close = () => back.remove();
    for (const [label, fn, id] of buttons) {
        const b = document.createElement("button");
        b.className = "tool";
        b.textContent = label;
        if (id) b.id = id;
        b.addEventListener("click", fn);
        foot.appendChild(b);
    }
    box.append(head, body, foot);
    back.appendChild(box);
    document.body.appendChild(back);
    return { el: box, close };
}
