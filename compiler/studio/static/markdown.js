// The language server's hover markdown as DOM nodes (text only: nothing is parsed as HTML).
// Fenced code blocks become <pre>, "- " lines a list, **strong**, *em* and `code` spans, "---" a rule.

export function markdownNodes(markdown) {
  const out = [];
  const parts = markdown.split(/```[a-z]*\n?/);
  parts.forEach((part, i) => {
    if (i % 2 === 1) {
      const pre = document.createElement("pre");
      pre.textContent = part.replace(/\n$/, "");
      out.push(pre);
      return;
    }
    for (const block of part.split(/\n{2,}/)) {
      if (!block.trim()) continue;
      if (block.trim() === "---") {
        out.push(document.createElement("hr"));
        continue;
      }
      const lines = block.split("\n");
      if (lines.every((line) => line.startsWith("- "))) {
        const list = document.createElement("ul");
        for (const line of lines) {
          const item = document.createElement("li");
          inline(unescape(line.slice(2)), item);
          list.append(item);
        }
        out.push(list);
        continue;
      }
      const p = document.createElement("p");
      inline(unescape(block), p);
      out.push(p);
    }
  });
  return out;
}

function unescape(text) {
  return text.replace(/\\([\\`*_{}[\]()#+\-.!<>|~])/g, "$1");
}

function inline(text, parent) {
  for (const piece of text.split(/(\*\*[^*]+\*\*|`[^`]+`|\*[^*\s][^*]*\*)/)) {
    if (!piece) continue;
    let node;
    if (piece.startsWith("**") && piece.endsWith("**")) {
      node = document.createElement("strong");
      node.textContent = piece.slice(2, -2);
    } else if (piece.length > 2 && piece.startsWith("*") && piece.endsWith("*")) {
      node = document.createElement("em");
      node.textContent = piece.slice(1, -1);
    } else if (piece.startsWith("`") && piece.endsWith("`")) {
      node = document.createElement("code");
      node.textContent = piece.slice(1, -1);
    } else {
      node = document.createTextNode(piece);
    }
    parent.append(node);
  }
}
