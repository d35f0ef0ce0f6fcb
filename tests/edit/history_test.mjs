// hexc edit's undo history (compiler/edit/page/history.js) is bounded: at most kSteps steps back, at most kChars
// characters of documents, the oldest dropped first, and what it keeps undoes and redoes exactly. Usage: node
// tests/edit/history_test.mjs (from the source root). Negative control: the same checks on the module with its bounds
// lifted (as it was: a copy of the document per step, for good) must fail.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

const source = readFileSync('compiler/edit/page/history.js', 'utf8');
const load = (text) => import('data:text/javascript;base64,' + Buffer.from(text).toString('base64'));

function checkBounded({ History, kSteps, kChars }) {
  // 1000 edits of a small document: the last kSteps are kept, each undone to the document before it, then no more.
  const h = new History();
  let doc = { name: 'rock', n: 0 };
  for (let i = 1; i <= 1000; ++i) {
    h.remember(doc, null, i * 2000);
    doc = { name: 'rock', n: i };
  }
  assert.equal(h.past.length, kSteps);
  for (let i = 999; i >= 1000 - kSteps; --i) assert.deepEqual((doc = h.undo(doc)), { name: 'rock', n: i });
  assert.equal(h.undo(doc), null);
  assert.deepEqual(h.redo(doc), { name: 'rock', n: 1001 - kSteps });
  // A document of about 1 MiB (the largest the server compiles), edited 100 times: at most kChars characters kept.
  const big = new History();
  const padding = 'x'.repeat(1 << 20);
  for (let i = 0; i < 100; ++i) big.remember({ padding, n: i }, null, i * 2000);
  const kept = big.past.reduce((n, s) => n + s.length, 0);
  assert.ok(kept <= kChars, `${kept} characters kept`);
  assert.equal(big.past.length, Math.floor(kChars / JSON.stringify({ padding, n: 99 }).length));
  // A drag is one step: the same control within a second of its last change.
  const drag = new History();
  for (let i = 0; i < 50; ++i) drag.remember({ n: i }, 'falloff', i * 10);
  assert.equal(drag.past.length, 1);
}

const real = await load(source);
const unbounded = source.replace(/kSteps = \d+/, 'kSteps = 1e9').replace(/kChars = [^;]+;/, 'kChars = 1e12;');
assert.notEqual(unbounded, source);
checkBounded(real);
const lifted = await load(unbounded);  // its History, judged against the bounds of the real one
assert.throws(() => checkBounded({ History: lifted.History, kSteps: real.kSteps, kChars: real.kChars }));
console.log('history: bounded, and the unbounded variant fails the checks');
