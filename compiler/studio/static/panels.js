// The page's panels: what the phrase means (explain tables and what changed), the refinement
// chips, the history strip, the export buttons and their warnings, the problem banner.

function element(tag, { className, text } = {}) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

export function showMaterials(container, materials) {
  container.replaceChildren(
    ...materials.map((m) => {
      const article = element("article");
      const title = element("h2");
      if (m.hex) {
        const swatch = element("span", { className: "swatch" });
        swatch.style.background = m.hex;
        title.append(swatch);
      }
      title.append(m.name);
      article.append(title);
      if (m.changes.length) {
        article.append(element("pre", { className: "changes", text: "changed:\n" + m.changes.join("\n") }));
      }
      article.append(element("pre", { text: m.explain.join("\n") }));
      return article;
    }),
  );
}

export function showChips(container, words, onPick) {
  container.replaceChildren(
    ...words.map((word) => {
      const chip = element("button", { text: word });
      chip.type = "button";
      chip.addEventListener("click", () => onPick(word));
      return chip;
    }),
  );
}

// The history strip: a step's item is kept while the step is (by its id), so an edit changes a
// class and adds an item rather than rebuilding every thumbnail; `pictures`: step id -> thumbnail.
export function showHistory(container, summary, pictures) {
  const before = new Map([...container.children].map((item) => [item.dataset.step, item]));
  const items = summary.steps.map((step, i) => {
    let item = before.get(String(step.id));
    if (!item) {
      item = element("li");
      item.dataset.step = String(step.id);
      item.append(element("img"), element("span"));
    }
    const [image, label] = item.children;
    if (label.textContent !== step.label) {
      label.textContent = step.label;
      image.alt = step.label;
    }
    const picture = pictures.get(step.id);
    if (picture && image.getAttribute("src") !== picture) image.src = picture;
    item.className = i === summary.at ? "current" : "";
    return item;
  });
  const same = items.length === container.children.length && items.every((item, i) => container.children[i] === item);
  if (!same) container.replaceChildren(...items);
}

export function showExports(container, exports, onExport) {
  container.replaceChildren(
    ...exports.map((kind) => {
      const button = element("button", { text: kind.label });
      button.type = "button";
      button.dataset.export = kind.key;
      button.addEventListener("click", () => onExport(kind, button));
      return button;
    }),
  );
}

export function showNotes(container, notes) {
  container.replaceChildren(...notes.map((note) => element("li", { text: note })));
}

export class Problem {
  constructor(node) {
    this.node = node;
  }
  show(message) {
    this.node.textContent = message;
    this.node.hidden = false;
  }
  clear() {
    this.node.hidden = true;
    this.node.textContent = "";
  }
}

// A small picture of the canvas for the history strip.
export function thumbnail(canvas, size = 96) {
  const small = document.createElement("canvas");
  small.width = size;
  small.height = size;
  small.getContext("2d").drawImage(canvas, 0, 0, size, size);
  return small.toDataURL("image/png");
}
