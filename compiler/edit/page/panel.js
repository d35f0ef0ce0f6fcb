// The settings panel, made from the material schema (materials/material.schema.json) and the document: one control per
// hex-tiling setting of the material and of the selected slot, with its range, default, unit and a reset, and the
// slot's own keys. A control reports (pointer, value) edits; which of them are uniforms is the page's to decide.

// Slider spans for settings the schema leaves unbounded (or bounds far beyond what is useful to drag through); the
// number box beside each slider takes any value the schema allows.
const kSpans = { tiling: [0.1, 64, 'log'], rotation: [0, 2], rotationrange: [-360, 360], scalerange: [0.1, 10, 'log'],
                 rotationsteps: [0, 24], offsetsteps: [0, 64], width: [0.005, 1] };  // width: the layers', above 0

// The document's slots as the panel and the server name them: the material's own, then each layer's, named
// `<layer>_<slot>` (docs/material-format.md#layers), with their JSON pointers and the layer whose settings they inherit.
export function slotEntries(doc) {
  const list = x => (Array.isArray(x) ? x : []);  // an invalid document still shows what it has
  const own = list(doc.slots).map((slot, i) => ({ slot, name: slot.name, pointer: `/slots/${i}`, layer: null }));
  const layered = list(doc.layers).flatMap((layer, l) => list(layer.slots).map((slot, i) => ({ slot, name: `${layer.name}_${slot.name}`,
                                                                                               pointer: `/layers/${l}/slots/${i}`, layer })));
  return [...own, ...layered];
}

// The effective value of `key` for the slot at `slotIndex` (null: the material's): the slot's own, else its layer's,
// else the material's, else the schema's default. `inherited`: what the slot would have without its own.
export function effective(doc, slotIndex, key, schemaDefault, { inherited = false } = {}) {
  const e = slotIndex === null ? null : slotEntries(doc)[slotIndex];
  const levels = [inherited ? null : e?.slot, e?.layer, doc];
  const level = levels.find(l => l?.hextiling?.[key] !== undefined);
  return level ? level.hextiling[key] : schemaDefault;
}

function element(tag, attributes = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes)) if (v !== undefined) e.setAttribute(k, v);
  for (const c of children) e.append(c);
  return e;
}

// A value rounded to what the slider resolves, so that the file gets 0.3 rather than 0.30000000000000004.
function rounded(x, integer) {
  return integer ? Math.round(x) : Number(x.toPrecision(4));
}

// What a schema property allows: the range of a number (or of each array item), its components and whether whole.
function describe(p) {
  if (p.oneOf && p.oneOf.some(o => o.type === 'array')) return { ...describe(p.oneOf.find(o => o.type === 'array')), either: true };
  if (p.type === 'array') {
    const item = p.items || {};
    return { ...describe(item), count: p.minItems };
  }
  const integer = p.type === 'integer';
  const min = p.minimum ?? p.exclusiveMinimum;
  return { integer, min, max: p.maximum, exclusiveMin: p.exclusiveMinimum !== undefined, count: 1 };
}

export class Panel {
  constructor(root, schema, onEdit) {
    this.root = root;
    this.schema = schema;
    // (pointer, value or undefined to remove, {slots, key, param: the layer blend's parameter}, a step of a slider's
    // drag) => void
    this.onEdit = onEdit;
    this.slot = 0;
    this.layer = 0;          // the layer the "layer weight" view shows
    this.open = { material: true, layers: true, overrides: false };  // which collapsible sections are open, kept across renders
    this.lock = false;       // tiling locked to square texels
    this.textureSize = () => null;  // (slot index) => [width, height] of its texture once loaded, set by the page
  }

  get hextiling() { return this.schema.$defs.hextiling.properties; }

  render(doc) {
    this.doc = doc;
    this.slots = slotEntries(doc);
    const slots = this.slots.length;
    this.slot = Math.max(0, Math.min(this.slot, slots - 1));
    const layered = doc.layer_blend && typeof doc.layer_blend === 'object' && Array.isArray(doc.layers);
    this.layer = Math.max(0, Math.min(this.layer, (layered ? doc.layers.length : 1) - 1));
    this.root.replaceChildren(this.section('Material', null, 'material'), ...(layered ? [this.layerSection()] : []),
                              ...(slots ? [this.slotSection()] : []));
  }

  // Every edit of a control goes here: a change of the layers' mode writes the whole `layer_blend`, since `height`
  // (the role heights come from) is required in height mode and refused in linear mode.
  edit(pointer, value, target, drag) {
    if (pointer !== '/layer_blend/mode') return this.onEdit(pointer, value, target, drag);
    const blend = { ...this.doc.layer_blend };
    if (value === undefined) delete blend.mode; else blend.mode = value;
    if (blend.mode === 'height') {
      const first = (this.doc.layers[0]?.slots || []).find(s => s.kind === 'scalar')?.name;  // a role of one channel
      blend.height ??= this.heightRole ?? first;
    } else if (blend.height !== undefined) {
      this.heightRole = blend.height;  // back in height mode, the role it had
      delete blend.height;
    }
    this.onEdit('/layer_blend', blend, target);
    this.render(this.doc);  // the width control shows in height mode only
  }

  // The layers' blend (docs/material-format.md#layers): its mode and, by mode, width, and what it keeps; and the layer
  // whose weight the page's "layer weight" view shows.
  layerSection() {
    const box = this.collapsible('Layer blend', 'layers');
    const blend = this.doc.layer_blend, defs = this.schema.properties.layer_blend.properties;
    const keys = ['mode', ...(blend.mode === 'height' ? ['width'] : []), 'skip_below', 'arrays'];
    for (const key of keys)
      box.append(this.control(key, defs[key], `/layer_blend/${key}`, blend[key], defs[key].default, { slots: [], key, param: `layer_blend_${key}` }));
    const picker = element('select', { id: 'layer-select', 'aria-label': 'layer' });
    this.doc.layers.forEach((l, i) => picker.append(element('option', { value: i }, `${i}: ${l.name}`)));
    picker.value = String(this.layer);
    picker.addEventListener('change', () => { this.layer = Number(picker.value); this.onLayer?.(this.layer); });
    box.append(element('div', { class: 'control' }, element('label', { title: 'the layer the "layer weight" view shows' }, 'weight view'), picker));
    return box;
  }

  // A section that folds away (its summary stays), open as it was left.
  collapsible(title, name) {
    const box = element('details', { class: 'settings', id: `section-${name}` }, element('summary', {}, element('h2', {}, title)));
    box.open = this.open[name];
    box.addEventListener('toggle', () => { this.open[name] = box.open; });
    return box;
  }

  // Material-wide settings (slotIndex null) or one slot's overrides, each key of the schema's hextiling. A material
  // setting reaches the slots that neither set it nor have a layer that does.
  section(title, slotIndex, name) {
    const box = this.collapsible(title, name);
    const entry = slotIndex === null ? null : this.slots[slotIndex];
    for (const [key, p] of Object.entries(this.hextiling)) {
      if (slotIndex !== null && (key === 'projection' || key === 'planesharpness')) continue;  // material-wide only
      const base = slotIndex === null ? '/hextiling' : `${entry.pointer}/hextiling`;
      const own = slotIndex === null ? this.doc.hextiling?.[key] : entry.slot.hextiling?.[key];
      const inherited = effective(this.doc, slotIndex, key, p.default, { inherited: true });
      const inherits = e => e.slot.hextiling?.[key] === undefined && e.layer?.hextiling?.[key] === undefined;
      const slots = slotIndex === null ? this.slots.flatMap((e, i) => (inherits(e) ? [i] : [])) : [slotIndex];
      box.append(this.control(key, p, `${base}/${key}`, own, inherited, { slots, key }, { shown: key === 'taps' ? 'the mask\'s' : undefined }));
    }
    return box;
  }

  slotSection() {
    const i = this.slot, { slot, pointer, name } = this.slots[i];
    const picker = element('select', { id: 'slot-select', 'aria-label': 'slot' });
    this.slots.forEach((e, k) => picker.append(element('option', { value: k }, `${e.name} (${e.slot.kind})`)));
    picker.value = String(i);
    picker.addEventListener('change', () => { this.slot = Number(picker.value); this.render(this.doc); this.onSlot?.(this.slot); });
    const slotDefs = this.schema.$defs.slot.properties;
    const box = element('section', { class: 'settings' }, element('h2', {}, 'Slot ', picker),
                        element('div', { class: 'texture' }, `texture ${slot.texture}`));
    const keys = ['kind', 'colorspace', ...(slot.kind === 'scalar' ? ['channel'] : []), ...(slot.kind === 'normal' ? ['flip_y'] : [])];
    const required = this.schema.$defs.slot.required;
    // colorspace's default follows the kind (docs/material-format.md); a required key has none, and no reset.
    const defaults = { colorspace: slot.kind === 'color' ? 'srgb' : 'linear' };
    for (const key of keys)
      box.append(this.control(key, slotDefs[key], `${pointer}/${key}`, slot[key], slotDefs[key].default ?? defaults[key], { slots: [i], key },
                              { required: required.includes(key) }));
    if (slot.height_blend) {
      const w = slotDefs.height_blend.properties.width;
      box.append(this.control('height_blend width', w, `${pointer}/height_blend/width`, slot.height_blend.width, w.default,
                              { slots: [i], key: 'heightwidth' }));
    }
    box.append(this.section(`${name}: hex-tiling overrides`, i, 'overrides'));
    return box;
  }

  // One setting: its editor, the value's default (inherited for a slot) and unit, and a reset that removes the key.
  // `shown`: what the default is when it is no value (taps: the mask's); a `required` key has no default and no reset.
  control(label, p, pointer, own, inherited, target, { shown, required = false } = {}) {
    const value = own !== undefined ? own : inherited;
    const row = element('div', { class: own !== undefined ? 'control own' : 'control', 'data-pointer': pointer });
    const unit = p['x-unit'] ? ` ${p['x-unit']}` : '';
    const defaultText = required ? 'required' : `default ${shown ?? JSON.stringify(inherited)}`;
    const reset = element('button', { class: 'reset', title: 'remove this key: back to the default' }, '↺');
    reset.disabled = own === undefined;
    reset.addEventListener('click', () => this.edit(pointer, undefined, target));
    row.append(element('label', { title: p.description || '' }, label), this.editor(label, p, pointer, value, target), required ? '' : reset,
               element('span', { class: 'default' }, `${unit ? unit.trim() + ', ' : ''}${defaultText}`));
    if (label === 'tiling') row.append(this.tilingLock(pointer, value, target));
    return row;
  }

  // The tiling lock: the second repeat follows the first so that a texel is square on the surface. A w x h texture tiled
  // [tx, ty] covers 1 / (tx w) by 1 / (ty h) of a uv unit per texel: square when ty = tx w / h.
  tilingLock(pointer, value, target) {
    const size = this.textureSize(this.slot);
    const box = element('input', { type: 'checkbox', class: 'lock' });
    box.checked = this.lock;
    box.disabled = !size;
    const squared = () => {
      const tx = Array.isArray(value) ? value[0] : value;
      return [tx, rounded(tx * size[0] / size[1], false)];
    };
    box.addEventListener('change', () => {
      this.lock = box.checked;
      if (!this.lock) return;
      this.onEdit(pointer, squared(), target);
      this.render(this.doc);  // the boxes show the second repeat the lock set
    });
    const why = size ? `keep texels square: the second repeat is the first × ${size[0]}/${size[1]} (the slot's texture)` : 'no texture loaded yet';
    return element('label', { class: 'lock', title: why }, box, ' square texels');
  }

  editor(label, p, pointer, value, target) {
    const choices = p.enum || (p.oneOf && p.oneOf.some(o => o.const) ? [1, 2, 3, 'adaptive'] : null);
    if (p.type === 'boolean') {
      const box = element('input', { type: 'checkbox' });
      box.checked = !!value;
      box.addEventListener('change', () => this.edit(pointer, box.checked, target));
      return box;
    }
    if (choices) {
      const select = element('select', {});
      if (value === undefined) select.append(element('option', { value: '' }, '(default)'));
      for (const c of choices) select.append(element('option', { value: JSON.stringify(c) }, String(c)));
      select.value = value === undefined ? '' : JSON.stringify(value);
      select.addEventListener('change', () => this.edit(pointer, JSON.parse(select.value), target));
      return select;
    }
    return this.sliders(label, p, pointer, value, target);
  }

  // A slider and a number box per component; an edit writes the whole value (a number, or the array).
  sliders(label, p, pointer, value, target) {
    const d = describe(p), span = kSpans[label] || [];
    const count = d.either ? 2 : d.count;
    const values = Array.isArray(value) ? [...value] : Array(count).fill(value);
    const min = span[0] ?? d.min ?? 0, max = span[1] ?? d.max ?? 1, log = span[2] === 'log';
    const toSlider = x => log ? Math.log(x / min) / Math.log(max / min) : (x - min) / (max - min);
    const fromSlider = t => log ? min * Math.pow(max / min, t) : min + t * (max - min);
    const box = element('span', { class: 'sliders' }), sliders = [], numbers = [];
    const write = drag => {
      const size = label === 'tiling' && this.lock && this.textureSize(this.slot);
      if (size) {
        values[1] = rounded(values[0] * size[0] / size[1], false);
        numbers[1].value = String(values[1]);
        sliders[1].value = String(toSlider(values[1]));
      }
      const out = !d.either || Array.isArray(value) || values[0] !== values[1] ? values.slice(0, count) : values[0];
      this.edit(pointer, count === 1 ? values[0] : out, target, drag);
    };
    for (let k = 0; k < count; ++k) {
      const slider = element('input', { type: 'range', min: 0, max: 1, step: d.integer ? 1 / Math.max(1, max - min) : 0.001 });
      const number = element('input', { type: 'number', step: d.integer ? 1 : 'any', min: d.exclusiveMin ? undefined : d.min, max: d.max });
      slider.value = String(toSlider(values[k]));
      number.value = String(values[k]);
      slider.addEventListener('input', () => {
        values[k] = rounded(fromSlider(Number(slider.value)), d.integer);
        number.value = String(values[k]);
        write(true);
      });
      number.addEventListener('change', () => {
        if (number.value === '' || !Number.isFinite(Number(number.value))) return;
        const typed = d.integer ? Math.round(Number(number.value)) : Number(number.value);
        // Refused here, not by a compile: a setting that is a uniform would draw it without one.
        const below = d.exclusiveMin ? typed <= d.min : typed < d.min;
        if (below || typed > d.max) {
          const range = `${d.exclusiveMin ? '(' : '['}${d.min ?? '-∞'}, ${d.max ?? '∞'}]`;
          this.onRefuse?.(`${pointer}: ${typed} is outside ${range}, the range the material format allows; ${label} stays ${values[k]}`);
          number.value = String(values[k]);
          return;
        }
        values[k] = typed;
        slider.value = String(toSlider(values[k]));
        write();
      });
      box.append(slider, number);
      sliders.push(slider);
      numbers.push(number);
    }
    return box;
  }
}
