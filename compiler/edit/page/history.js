// Undo and redo over every change of the document in this session: panel edits (a slider's drag is one step), a
// reload from disk, taking the file's version. Each step is the document before it, as JSON text. Bounded: at most
// kSteps steps back and kChars characters of them (a material is at most 1 MiB, what the server compiles), the
// oldest dropped first, so that a long session of a large material does not keep a copy of it per edit for good.
export const kSteps = 200;
export const kChars = 16 << 20;

export class History {
  constructor() {
    Object.assign(this, { past: [], future: [], pointer: null, at: 0 });
  }

  // Before a change of `doc` (the document as it is): a step back, unless the change continues the last one (the same
  // `pointer`, a control being dragged, within a second of it at `now`).
  remember(doc, pointer, now) {
    if (!(pointer !== null && pointer === this.pointer && now - this.at < 1000)) keep(this.past, JSON.stringify(doc));
    Object.assign(this, { future: [], pointer, at: now });
  }

  // The document a step back (undo) or forward (redo) from `doc`, or null when there is none.
  undo(doc) { return this.travel(this.past, this.future, doc); }
  redo(doc) { return this.travel(this.future, this.past, doc); }

  travel(from, to, doc) {
    if (!from.length) return null;
    keep(to, JSON.stringify(doc));
    this.pointer = null;
    return JSON.parse(from.pop());
  }
}

function keep(stack, text) {
  stack.push(text);
  let chars = stack.reduce((n, s) => n + s.length, 0);
  while (stack.length > kSteps || (stack.length > 1 && chars > kChars)) chars -= stack.shift().length;
}
