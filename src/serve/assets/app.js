// ekb serve: the page. No framework, no build step. Every text from the file is set with
// textContent (never parsed as HTML). The page keeps the file as loaded (`base`), the text
// its edits apply to (`work`: the base, plus any fix applied), and the value of every field;
// as the person types it sends `work` and the changed values to /api/check, where the server
// makes the edits with the same lossless editor that saves (crate::edit::apply) and checks
// the result as `ekb check` does.
'use strict';

const LANGUAGES = [['English', 'English'], ['IsiZulu', 'isiZulu'], ['Kinyarwanda', 'Kinyarwanda']];
const PARTS = { pose: ['x', 'y', 'theta'], gestureTarget: ['x', 'y', 'z'] };
const SEVERITY_ORDER = { error: 0, warning: 1, info: 2, hint: 3 };
const DEBOUNCE_MS = 150;

const state = {
  base: null,          // {name, text, version, fields, tour}: the file as loaded
  work: '',            // the text the edits apply to
  workValues: new Map(), // "id|key" -> value in `work`
  values: new Map(),   // "id|key" -> value in the form
  workTour: [],        // the tour's stops in `work`
  tour: [],            // the tour's stops in the page
  added: [],           // ids of locations added in the page (not yet in `work`)
  removed: [],         // ids of locations removed in the page
  lastChecked: null,   // the last /api/check answer
  undo: [],
  redo: [],
  lastPush: { at: 0, slot: null },
  seq: 0,
  saving: false,
  conflicts: null,
};

const $ = (selector, root = document) => root.querySelector(selector);
const slot = (id, key) => `${id}|${key}`;

function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value === undefined || value === null || value === false) continue;
    if (name === 'text') node.textContent = value;
    else node.setAttribute(name, value === true ? '' : String(value));
  }
  for (const child of children) if (child) node.append(child);
  return node;
}

function setState(name, status) {
  document.body.dataset.state = name;
  if (status !== undefined) $('#status').textContent = status;
}

async function api(path, body) {
  const init = body === undefined
    ? { credentials: 'same-origin' }
    : { method: 'POST', credentials: 'same-origin', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) };
  const response = await fetch(path, init);
  const type = response.headers.get('Content-Type') || '';
  const data = type.startsWith('application/json') ? await response.json() : await response.text();
  return { status: response.status, data };
}

// ---- The values -------------------------------------------------------------------------

function valuesOf(fields) {
  const map = new Map();
  for (const field of fields) map.set(slot(field.id, field.key), field.value);
  return map;
}

function edits() {
  const out = [];
  for (const [where, value] of state.values) {
    if (state.removed.includes(Number(where.split('|')[0]))) continue;
    const before = state.workValues.get(where);
    if (value === before || (before === undefined && value === '')) continue;
    const [id, key] = where.split('|');
    out.push({ id: Number(id), key, value });
  }
  return out;
}

const sameTour = (a, b) => a.length === b.length && a.every((id, i) => id === b[i]);
const tourChanged = () => !sameTour(state.tour, state.workTour);

function isDirty() {
  return state.work !== state.base.text || edits().length > 0 || tourChanged()
    || state.added.length > 0 || state.removed.length > 0;
}

// What the page sends besides the edits: the tour, the locations added and removed.
function changes(request) {
  if (tourChanged()) request.tour = state.tour;
  if (state.added.length) request.add_locations = state.added;
  if (state.removed.length) request.remove_locations = state.removed;
  return request;
}

// ---- The form ---------------------------------------------------------------------------

function fieldId(id, key, part) {
  return `f-${id}-${key}${part ? '-' + part : ''}`;
}

function poseKey(id, fields) {
  if (fields.some((f) => f.id === id && f.key === 'robotLocationPose')) return 'robotLocationPose';
  if (fields.some((f) => f.id === id && f.key === 'robotLocation')) return 'robotLocation';
  return fields.some((f) => f.key === 'robotLocationPose') ? 'robotLocationPose' : 'robotLocation';
}

function textField(id, key, label, wide, multiline) {
  const input = multiline ? el('textarea', { rows: 2 }) : el('input', { type: 'text' });
  input.id = fieldId(id, key);
  Object.assign(input.dataset, { key, id: String(id) });
  input.value = state.values.get(slot(id, key)) || '';
  input.addEventListener('input', () => {
    if (multiline && /[\r\n]/.test(input.value)) input.value = input.value.replace(/[\r\n]+/g, ' ');
    changed(id, key, input.value);
  });
  const box = el('div', { class: wide ? 'field wide' : 'field', 'data-field': slot(id, key) },
    el('label', { for: input.id, text: label }), input, el('div', { class: 'findings' }));
  return box;
}

function splitValue(value) {
  return (value || '').trim().split(/[ \t]+/).filter((part) => part !== '');
}

function numbersField(id, key, parts, label) {
  const group = el('div', { class: 'numbers', role: 'group', 'aria-label': label });
  const inputs = [];
  const tokens = splitValue(state.values.get(slot(id, key)));
  parts.forEach((part, index) => {
    const input = el('input', { type: 'text', inputmode: 'decimal', size: 8 });
    input.id = fieldId(id, key, part);
    Object.assign(input.dataset, { key, id: String(id), part });
    input.value = tokens[index] || '';
    input.addEventListener('input', () => changed(id, key, joinParts(id, key, inputs)));
    inputs.push(input);
    group.append(el('span', { class: 'field' }, el('label', { for: input.id, text: part === 'theta' ? 'θ (degrees)' : part }), input));
  });
  return el('div', { class: 'field', 'data-field': slot(id, key) },
    el('span', { class: 'group-label', text: label }), group, el('div', { class: 'findings' }));
}

// The value of a pose or target from its parts: the value as written when the numbers are
// the same (so that its spacing is kept), else the parts joined by one space.
function joinParts(id, key, inputs) {
  const parts = inputs.map((input) => input.value.trim());
  const written = state.workValues.get(slot(id, key));
  const tokens = splitValue(written);
  const extra = tokens.slice(inputs.length);
  if (written !== undefined && tokens.length >= inputs.length && parts.every((p, i) => p === tokens[i])) return written;
  return parts.concat(extra).join(' ').trim();
}

function locationIds() {
  const seen = new Set();
  const order = [];
  for (const id of state.base.tour) if (!seen.has(id)) { seen.add(id); order.push(id); }
  const ids = allIds();
  for (const id of ids) if (!seen.has(id)) { seen.add(id); order.push(id); }
  return order.filter((id) => !state.removed.includes(id) && (ids.includes(id) || state.base.tour.includes(id)));
}

function buildForm() {
  const box = $('#locations');
  box.replaceChildren();
  const fields = state.lastChecked ? state.lastChecked.fields : state.base.fields;
  const hasArm = fields.some((f) => f.key === 'gestureArm');
  const tourSet = new Set(state.base.tour);
  locationIds().forEach((id) => {
    const title = el('h2', { id: `title-${id}` });
    const description = state.values.get(slot(id, 'robotLocationDescription'));
    title.textContent = `Location ${id}${description ? ': ' + description : ''}${tourSet.has(id) ? '' : ' (not in the tour)'}`;
    const section = el('section', { 'data-location': String(id), id: `section-${id}`, 'aria-labelledby': title.id }, title);
    const remove = el('button', { type: 'button', class: 'remove-location', 'data-action': 'location-remove', text: `Remove location ${id}` });
    remove.addEventListener('click', () => removeLocation(id));
    section.append(remove);
    section.append(el('div', { class: 'findings', 'data-findings-of': String(id) }));
    section.append(el('div', { class: 'row' },
      textField(id, 'robotLocationDescription', 'Description', true, false)));
    section.append(el('div', { class: 'row' },
      numbersField(id, poseKey(id, fields), PARTS.pose, 'Pose (metres, degrees)'),
      numbersField(id, 'gestureTarget', PARTS.gestureTarget, 'Gesture target (metres)')));
    const table = el('table', { class: 'messages' });
    const head = el('tr', {}, el('th', { text: '' }));
    for (const [, name] of LANGUAGES) head.append(el('th', { scope: 'col', text: name }));
    table.append(el('thead', {}, head));
    const body = el('tbody');
    for (const [when, label] of [['pre', 'Before the gesture'], ['post', 'After the gesture']]) {
      const row = el('tr', {}, el('th', { scope: 'row', text: label }));
      for (const [suffix, name] of LANGUAGES) {
        const key = `${when}GestureMessage${suffix}`;
        row.append(el('td', {}, textField(id, key, `${label}, ${name}`, true, true)));
      }
      body.append(row);
    }
    table.append(body);
    section.append(table);
    const last = el('div', { class: 'row' }, textField(id, 'culturalKnowledge', 'Culture words', true, false));
    if (hasArm) last.append(textField(id, 'gestureArm', 'Arm', false, false));
    section.append(last);
    box.append(section);
  });
}

function fillForm() {
  for (const input of document.querySelectorAll('[data-key][data-id]')) {
    if (input.tagName !== 'INPUT' && input.tagName !== 'TEXTAREA') continue;
    const value = state.values.get(slot(input.dataset.id, input.dataset.key)) || '';
    const next = input.dataset.part
      ? (splitValue(value)[PARTS[input.dataset.part === 'z' ? 'gestureTarget' : 'pose'].indexOf(input.dataset.part)] || '')
      : value;
    if (input.value !== next) input.value = next;
  }
}

// ---- Locations added and removed --------------------------------------------------------

function allIds() {
  return [...new Set([...state.values.keys()].map((where) => Number(where.split('|')[0])))];
}

function addLocation() {
  remember(null);
  const id = Math.max(0, ...allIds(), ...state.removed) + 1;
  state.added = state.added.concat([id]);
  state.values.set(slot(id, 'robotLocationDescription'), `New location ${id}`);
  state.lastPush = { at: 0, slot: null };
  buildForm();
  afterChange();
  const input = document.getElementById(fieldId(id, 'robotLocationDescription'));
  if (input) { input.scrollIntoView({ block: 'center' }); input.focus(); input.select(); }
}

function removeLocation(id) {
  remember(null);
  if (state.added.includes(id)) state.added = state.added.filter((other) => other !== id);
  else state.removed = state.removed.concat([id]);
  for (const where of [...state.values.keys()]) if (Number(where.split('|')[0]) === id) state.values.delete(where);
  state.tour = state.tour.filter((stop) => stop !== id);
  state.lastPush = { at: 0, slot: null };
  buildForm();
  afterChange();
}

// ---- The tour ---------------------------------------------------------------------------

function changeTour(next) {
  remember(null);
  state.tour = next;
  state.lastPush = { at: 0, slot: null };
  afterChange();
}

function renderTour() {
  const list = $('#tour-list');
  if (!list) return;
  list.replaceChildren();
  state.tour.forEach((id, index) => {
    const description = state.values.get(slot(id, 'robotLocationDescription'));
    const item = el('li', { 'data-stop': String(id) }, el('span', { class: 'stop-name', text: `Location ${id}${description ? ': ' + description : ''}` }));
    const button = (action, label, text, disabled, next) => {
      const b = el('button', { type: 'button', 'data-action': action, 'aria-label': label, text, disabled });
      b.addEventListener('click', () => changeTour(next()));
      return b;
    };
    const moved = (to) => () => { const next = state.tour.slice(); next.splice(index, 1); next.splice(to, 0, id); return next; };
    item.append(' ',
      button('tour-up', `Move stop ${index + 1} up`, '↑', index === 0, moved(index - 1)),
      button('tour-down', `Move stop ${index + 1} down`, '↓', index === state.tour.length - 1, moved(index + 1)),
      button('tour-remove', `Remove stop ${index + 1}`, 'Remove', false, () => state.tour.filter((_, i) => i !== index)));
    list.append(item);
  });
  const select = $('#tour-add-id');
  const ids = [...new Set([...state.values.keys()].map((where) => Number(where.split('|')[0])))].sort((a, b) => a - b);
  const chosen = select.value;
  select.replaceChildren(...ids.map((id) => el('option', { value: String(id), text: `Location ${id}` })));
  if (ids.map(String).includes(chosen)) select.value = chosen;
}

// ---- Editing, undo, redo ----------------------------------------------------------------

function snapshot() {
  return {
    work: state.work, workValues: new Map(state.workValues), values: new Map(state.values),
    workTour: state.workTour.slice(), tour: state.tour.slice(),
    added: state.added.slice(), removed: state.removed.slice(),
  };
}

function restore(snap) {
  state.work = snap.work;
  state.workValues = new Map(snap.workValues);
  state.values = new Map(snap.values);
  state.workTour = snap.workTour.slice();
  state.tour = snap.tour.slice();
  const sections = state.added.join() !== snap.added.join() || state.removed.join() !== snap.removed.join();
  state.added = snap.added.slice();
  state.removed = snap.removed.slice();
  if (sections) buildForm();
  fillForm();
  afterChange();
}

function remember(where) {
  const now = Date.now();
  if (where === null || where !== state.lastPush.slot || now - state.lastPush.at > 1000) {
    state.undo.push(snapshot());
    if (state.undo.length > 500) state.undo.shift();
    state.redo = [];
  }
  state.lastPush = { at: now, slot: where };
}

function changed(id, key, value) {
  const where = slot(id, key);
  remember(where);
  state.values.set(where, value);
  afterChange();
}

function undo() {
  if (!state.undo.length) return;
  state.redo.push(snapshot());
  restore(state.undo.pop());
  state.lastPush = { at: 0, slot: null };
}

function redo() {
  if (!state.redo.length) return;
  state.undo.push(snapshot());
  restore(state.redo.pop());
  state.lastPush = { at: 0, slot: null };
}

function afterChange() {
  renderTour();
  if (state.conflicts) return scheduleCheck();
  if (isDirty()) setState('dirty', 'Unsaved changes');
  else setState('clean', 'No unsaved changes');
  scheduleCheck();
}

let timer = null;
function scheduleCheck() {
  clearTimeout(timer);
  timer = setTimeout(runCheck, DEBOUNCE_MS);
}

async function runCheck() {
  const seq = ++state.seq;
  const request = changes({ text: state.work, edits: edits() });
  const { status, data } = await api('/api/check', request);
  if (seq !== state.seq) return; // a newer check is on its way
  if (status !== 200) {
    $('#status').textContent = `Cannot check: ${typeof data === 'string' ? data : JSON.stringify(data)}`;
    return;
  }
  state.lastChecked = data;
  showFindings(data);
  showTranslations(data.translations || []);
  refreshMap();
}

function showTranslations(statuses) {
  const box = $('#translations');
  box.replaceChildren();
  for (const status of statuses) {
    box.append(el('span', {
      class: 'translation', 'data-translation': status.code,
      title: `${status.translated} of ${status.total} messages translated, ${status.untranslated} untranslated`,
      text: `${status.language} ${status.translated_percent}%`,
    }));
  }
}

// ---- Findings ---------------------------------------------------------------------------

// The field a finding is about: the one on its line; for a value the file lacks
// (`missing-field`, which points at the location's first line), the key its message names.
function fieldOf(checked, finding) {
  if (finding.rule === 'missing-field' && finding.location_id !== null && finding.location_id !== undefined) {
    const named = (finding.message.match(/`([A-Za-z]+)`/) || [])[1];
    if (named && document.querySelector(`[data-field="${CSS.escape(slot(finding.location_id, named))}"]`)) {
      return { id: finding.location_id, key: named, missing: true };
    }
  }
  return checked.fields.find((field) => field.line === finding.line);
}

function showFindings(checked) {
  for (const box of document.querySelectorAll('.findings')) box.replaceChildren();
  for (const box of document.querySelectorAll('.has-error, .has-warning')) box.classList.remove('has-error', 'has-warning');
  for (const input of document.querySelectorAll('[aria-describedby^="finding-"]')) {
    input.removeAttribute('aria-describedby');
    input.removeAttribute('aria-invalid');
  }
  const lines = checked.text.split('\n');
  // In the order the server reads them (errors first, a consequence after its cause).
  const rank = new Map((checked.reading_order || []).map(([line, column, rule], index) => [`${line}:${column}:${rule}`, index]));
  const placeOf = (finding) => rank.get(`${finding.line}:${finding.column}:${finding.rule}`) ?? Infinity;
  const diagnostics = checked.check.diagnostics.slice().sort((a, b) =>
    placeOf(a) - placeOf(b) || (SEVERITY_ORDER[a.severity] ?? 9) - (SEVERITY_ORDER[b.severity] ?? 9) || a.line - b.line || a.column - b.column);
  const summary = [];
  diagnostics.forEach((finding, index) => {
    const field = fieldOf(checked, finding);
    let box = field && $(`[data-field="${CSS.escape(slot(field.id, field.key))}"]`);
    let target = null;
    const node = findingNode(finding, index, field ? null : lines[finding.line - 1]);
    if (box) {
      box.classList.add(`has-${finding.severity}`);
      $('.findings', box).append(node);
      target = $('input, textarea', box);
      // Screen readers read a field's findings with it.
      for (const input of box.querySelectorAll('input, textarea')) {
        const described = input.getAttribute('aria-describedby');
        input.setAttribute('aria-describedby', described ? `${described} ${node.id}` : node.id);
        if (finding.severity === 'error') input.setAttribute('aria-invalid', 'true');
      }
    } else {
      const id = finding.location_id;
      box = id !== null && id !== undefined && $(`[data-findings-of="${CSS.escape(String(id))}"]`);
      (box || $('[data-findings-of="file"]')).append(node);
    }
    summary.push({ finding, node, target });
  });
  renderSummary(checked.check.summary, summary);
}

function findingNode(finding, index, lineText) {
  const node = el('div', {
    class: 'finding', id: `finding-${index}`, 'data-rule': finding.rule, 'data-severity': finding.severity,
  });
  const head = el('div');
  head.append(el('span', { class: `sev-${finding.severity}`, text: finding.severity }), ' ',
    el('span', { class: 'rule', text: finding.rule }), el('span', { class: 'message', text: finding.message }));
  node.append(head);
  if (lineText !== undefined && lineText !== null) {
    const written = lineText.replace(/\r$/, '');
    node.append(el('pre', { 'aria-label': `Line ${finding.line} as written`, text: `${finding.line}: ${written}` }));
    node.append(lineEditor(finding.line, written, index));
  }
  if (finding.help) node.append(el('p', { class: 'help', text: finding.help }));
  if (finding.fix) {
    const button = el('button', { type: 'button', 'data-fix': finding.rule, text: `Fix: ${finding.fix.message}` });
    button.addEventListener('click', () => applyFix(finding.fix));
    node.append(button);
  }
  return node;
}

// A line that is no field, edited as text: it replaces the line, as a fix would.
function lineEditor(line, written, index) {
  const input = el('input', { type: 'text', id: `line-edit-${index}`, 'data-line-edit': String(line), size: 60 });
  input.value = written;
  const apply = el('button', { type: 'button', 'data-action': 'apply-line', text: 'Change the line' });
  apply.addEventListener('click', () => {
    if (input.value === written || /[\r\n]/.test(input.value)) return;
    applyFix({ edits: [{ line, column: 1, end_line: line, end_column: Array.from(written).length + 1, replacement: input.value }] });
  });
  return el('details', {}, el('summary', { text: 'Edit the line as text' }),
    el('label', { for: input.id, text: `Line ${line}` }), ' ', input, ' ', apply);
}

function renderSummary(counts, entries) {
  const nav = $('#summary');
  nav.replaceChildren();
  const errors = counts.errors ?? 0;
  const warnings = counts.warnings ?? 0;
  const others = entries.length - entries.filter((e) => e.finding.severity === 'error' || e.finding.severity === 'warning').length;
  const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;
  nav.append(el('strong', { 'data-summary': true, text: `${plural(errors, 'error')}, ${plural(warnings, 'warning')}, ${others} other` }));
  if (!entries.length) return;
  const list = el('ol');
  for (const { finding, node, target } of entries) {
    // No data-rule here: the hooks are on the findings themselves (SPEC §14).
    const link = el('a', { href: `#${node.id}`, class: `sev-${finding.severity}` });
    const where = finding.location_id !== null && finding.location_id !== undefined ? `location ${finding.location_id}` : `line ${finding.line}`;
    link.textContent = `${finding.severity} ${finding.rule} (${where}): ${finding.message}`;
    link.addEventListener('click', (event) => {
      event.preventDefault();
      node.scrollIntoView({ block: 'center' });
      (target || node).focus({ preventScroll: true });
    });
    if (!target) node.tabIndex = -1;
    list.append(el('li', {}, link));
  }
  nav.append(list);
}

// A fix's edits (1-based lines, columns in Unicode scalar values, end exclusive) applied
// to the text they were found in.
function applyEdits(text, fixEdits) {
  const chars = Array.from(text);
  const starts = [0];
  chars.forEach((c, i) => { if (c === '\n') starts.push(i + 1); });
  const offset = (line, column) => (starts[line - 1] ?? chars.length) + column - 1;
  const sorted = fixEdits.map((e) => ({ start: offset(e.line, e.column), end: offset(e.end_line, e.end_column), text: e.replacement }))
    .sort((a, b) => b.start - a.start);
  for (const e of sorted) chars.splice(e.start, e.end - e.start, ...Array.from(e.text));
  return chars.join('');
}

async function applyFix(fix) {
  const checked = state.lastChecked;
  if (!checked) return;
  remember(null);
  const text = applyEdits(checked.text, fix.edits);
  const { status, data } = await api('/api/check', { text, edits: [] });
  // `checked.text` already had the page's edits, locations and tour.
  if (status !== 200) return;
  state.work = data.text;
  state.workValues = valuesOf(data.fields);
  state.values = valuesOf(data.fields);
  state.workTour = data.tour.slice();
  state.tour = data.tour.slice();
  state.added = [];
  state.removed = [];
  state.lastChecked = data;
  buildForm();
  fillForm();
  renderTour();
  if (isDirty()) setState('dirty', 'Unsaved changes'); else setState('clean', 'No unsaved changes');
  showFindings(data);
  refreshMap();
}

// ---- Saving and conflicts ---------------------------------------------------------------

function loaded(file) {
  state.base = file;
  state.work = file.text;
  state.workValues = valuesOf(file.fields);
  state.workTour = file.tour.slice();
  $('#file-name').textContent = file.name;
  document.title = `${file.name} — ekb serve`;
}

async function save() {
  if (state.saving || state.conflicts) return;
  state.saving = true;
  setState('saving', 'Saving…');
  try {
    const request = changes({ base_version: state.base.version, edits: edits() });
    if (state.work !== state.base.text) request.text = state.work;
    const { status, data } = await api('/api/save', request);
    if (status === 200 && data.conflicts && data.conflicts.length) {
      showConflicts(data);
    } else if (status === 200) {
      const sections = state.added.length || state.removed.length;
      loaded(data);
      state.values = valuesOf(data.fields);
      state.tour = data.tour.slice();
      state.added = [];
      state.removed = [];
      if (sections) buildForm();
      fillForm();
      renderTour();
      const merged = data.merged ? ', merged with the changes on disk' : '';
      const dropped = data.fixes_dropped ? ' (the file had changed: apply your fixes again)' : '';
      setState('saved', `Saved${merged}${dropped}`);
      scheduleCheck();
    } else {
      setState('dirty', `Not saved: ${typeof data === 'string' ? data : JSON.stringify(data)}`);
    }
  } catch (error) {
    setState('dirty', `Not saved: ${error}`);
  } finally {
    state.saving = false;
  }
}

function showConflicts(disk) {
  state.conflicts = { disk, chosen: new Map() };
  setState('conflict', 'Someone else changed the same values: choose for each');
  const box = el('section', { 'data-conflict': true, 'aria-labelledby': 'title-conflict' },
    el('h2', { id: 'title-conflict', text: 'Changed on disk and here' }),
    el('p', { class: 'hint', text: 'The file changed on disk since you loaded it, and these values were changed on both sides. Nothing was saved. Choose which value to keep for each, then save again.' }));
  for (const conflict of disk.conflicts) {
    const row = el('div', { class: 'choice', 'data-key': conflict.key, 'data-id': String(conflict.id) });
    row.append(el('strong', { text: conflict.id === 0 ? 'The tour' : `Location ${conflict.id}, ${conflict.key}` }));
    const mine = el('button', { type: 'button', 'data-choose': 'mine' });
    mine.append('Keep mine: ', el('span', { class: 'value', text: conflict.mine }));
    const theirs = el('button', { type: 'button', 'data-choose': 'theirs' });
    theirs.append('Take theirs: ', el('span', { class: 'value', text: conflict.theirs ?? '(no line)' }));
    mine.addEventListener('click', () => choose(conflict, 'mine', row));
    theirs.addEventListener('click', () => choose(conflict, 'theirs', row));
    row.append(mine, theirs);
    box.append(row);
  }
  $('#conflict-box').replaceChildren(box);
  box.scrollIntoView({ block: 'start' });
}

function choose(conflict, side, row) {
  const { disk, chosen } = state.conflicts;
  chosen.set(slot(conflict.id, conflict.key), side === 'mine' ? conflict.mine : (conflict.theirs ?? ''));
  row.dataset.chosen = side;
  for (const button of row.querySelectorAll('button')) button.setAttribute('aria-pressed', String(button.dataset.choose === side));
  if (chosen.size < disk.conflicts.length) return;
  rebase(disk, chosen);
}

// The page now edits `disk`, the file on disk, with its own changed values on top and, for
// the values changed on both sides, those `chosen`.
function rebase(disk, chosen) {
  remember(null);
  const mine = new Map();
  for (const [where, value] of state.values) if (state.workValues.get(where) !== value) mine.set(where, value);
  const myTour = tourChanged() ? state.tour.slice() : null;
  loaded(disk);
  state.values = valuesOf(disk.fields);
  state.tour = myTour || disk.tour.slice();
  for (const [where, value] of mine) state.values.set(where, value);
  for (const [where, value] of chosen) {
    if (where === slot(0, 'tourSpecification')) state.tour = value.split(' ').filter((id) => id !== '').map(Number);
    else state.values.set(where, value);
  }
  state.conflicts = null;
  $('#conflict-box').replaceChildren();
  $('#disk-notice').replaceChildren();
  buildForm();
  afterChange();
}

// ---- A change on disk -------------------------------------------------------------------

const POLL_MS = 3000;
async function poll() {
  try {
    if (!state.base || state.saving || state.conflicts) return;
    const { status, data } = await api('/api/version');
    if (status !== 200 || data.version === state.base.version || state.saving) return;
    const notice = $('#disk-notice');
    if (notice.dataset.version === data.version) return;
    notice.dataset.version = data.version;
    const button = el('button', { type: 'button', 'data-action': 'reload', text: isDirty() ? 'Load it, keeping my edits' : 'Load it' });
    button.addEventListener('click', reload);
    notice.replaceChildren(el('p', { text: 'The file changed on disk since you loaded it (a colleague, git, ekb set).' }), button);
  } finally {
    setTimeout(poll, POLL_MS);
  }
}

// Loads the file on disk: the page's own edits are kept on top; a value changed on both
// sides is offered to choose, as a save would.
async function reload() {
  const { status, data } = await api('/api/file');
  if (status !== 200) return;
  const diskValues = valuesOf(data.fields);
  const conflicts = [];
  for (const [where, value] of state.values) {
    const before = state.workValues.get(where);
    if (value === before) continue;
    const theirs = diskValues.get(where);
    if (theirs !== before && theirs !== value) {
      const [id, key] = where.split('|');
      conflicts.push({ id: Number(id), key, mine: value, theirs: theirs ?? null });
    }
  }
  if (tourChanged() && !sameTour(data.tour, state.workTour) && !sameTour(data.tour, state.tour)) {
    conflicts.push({ id: 0, key: 'tourSpecification', mine: state.tour.join(' '), theirs: data.tour.join(' ') });
  }
  $('#disk-notice').replaceChildren();
  if (conflicts.length) showConflicts({ ...data, conflicts });
  else rebase(data, new Map());
}

// ---- The map ----------------------------------------------------------------------------

let mapPending = false;
async function refreshMap() {
  if (mapPending || dragging) return;
  mapPending = true;
  try {
    const response = await fetch('/api/map', { credentials: 'same-origin' });
    if (!response.ok) return;
    const svgText = await response.text();
    const parsed = new DOMParser().parseFromString(svgText, 'image/svg+xml');
    const svg = parsed.documentElement;
    if (svg.nodeName !== 'svg') return;
    const plot = svg.querySelector('#plot');
    if (!plot) return;
    $('#map-section').hidden = false;
    const node = document.importNode(svg, true);
    // Its handles are controls: the drawing is a group of them, not one image.
    node.setAttribute('role', 'group');
    // `data-location` names the page's sections: the drawing's own become data-map-location.
    for (const item of node.querySelectorAll('[data-location]')) {
      item.setAttribute('data-map-location', item.getAttribute('data-location'));
      item.removeAttribute('data-location');
    }
    for (const pose of node.querySelectorAll('g.pose[data-map-location]')) {
      pose.setAttribute('data-pose-handle', pose.getAttribute('data-map-location'));
      pose.setAttribute('tabindex', '0');
      pose.setAttribute('role', 'button');
      pose.setAttribute('aria-label', `Pose of location ${pose.getAttribute('data-map-location')}: drag to move, Shift-drag to turn, or edit its fields`);
      pose.addEventListener('pointerdown', (event) => startDrag(event, node, pose, 'pose'));
    }
    for (const target of node.querySelectorAll('g.gesture[data-map-location]')) {
      target.setAttribute('data-target-handle', target.getAttribute('data-map-location'));
      target.setAttribute('role', 'img');
      target.setAttribute('aria-label', `Gesture target of location ${target.getAttribute('data-map-location')}: drag to move, or edit its fields`);
      target.addEventListener('pointerdown', (event) => startDrag(event, node, target, 'target'));
    }
    $('#map-box').replaceChildren(node);
  } finally {
    mapPending = false;
  }
}

let dragging = null;
// Drags a stop's pose (its x and y), or with Shift turns its heading (θ); or drags a
// gesture target (its x and y). The fields follow; the map is redrawn after the check.
function startDrag(event, svg, handle, kind) {
  const plot = svg.querySelector('#plot');
  const [ox, oy] = (plot.getAttribute('data-origin') || '0 0').split(' ').map(Number);
  const scale = Number(plot.getAttribute('data-scale')) || 1;
  const id = Number(handle.getAttribute(kind === 'target' ? 'data-target-handle' : 'data-pose-handle'));
  const fields = state.lastChecked ? state.lastChecked.fields : state.base.fields;
  const key = kind === 'target' ? 'gestureTarget' : poseKey(id, fields);
  const turning = kind === 'pose' && event.shiftKey;
  const transform = handle.getAttribute('transform') || '';
  const [tx, ty] = ((transform.match(/translate\(([^)]*)\)/) || [])[1] || '0 0').split(/[ ,]+/).map(Number);
  let rotate = (transform.match(/rotate\(([^)]*)\)/) || [])[1] || '0';
  dragging = { id, key };
  handle.setPointerCapture(event.pointerId);
  event.preventDefault();
  remember(null);
  const set = (index, value) => {
    const tokens = splitValue(state.values.get(slot(id, key)));
    while (tokens.length < 3) tokens.push('0');
    tokens[index] = value;
    state.values.set(slot(id, key), tokens.join(' '));
  };
  const move = (e) => {
    const point = svg.createSVGPoint();
    point.x = e.clientX;
    point.y = e.clientY;
    const local = point.matrixTransform(svg.getScreenCTM().inverse());
    const x = ((local.x - ox) / scale).toFixed(2);
    const y = ((oy - local.y) / scale).toFixed(2);
    if (turning) {
      // SVG turns clockwise: the heading is the angle to the pointer, counter-clockwise.
      const theta = Math.round((Math.atan2(-(local.y - ty), local.x - tx) * 180) / Math.PI);
      rotate = String(-theta);
      handle.setAttribute('transform', `translate(${tx} ${ty}) rotate(${rotate})`);
      set(2, String(theta));
    } else if (kind === 'pose') {
      handle.setAttribute('transform', `translate(${local.x.toFixed(1)} ${local.y.toFixed(1)}) rotate(${rotate})`);
      set(0, x);
      set(1, y);
    } else {
      const circle = handle.querySelector('circle');
      const line = handle.querySelector('line');
      if (circle) { circle.setAttribute('cx', local.x.toFixed(1)); circle.setAttribute('cy', local.y.toFixed(1)); }
      if (line) { line.setAttribute('x2', local.x.toFixed(1)); line.setAttribute('y2', local.y.toFixed(1)); }
      set(0, x);
      set(1, y);
    }
    fillForm();
  };
  const up = () => {
    handle.removeEventListener('pointermove', move);
    handle.removeEventListener('pointerup', up);
    dragging = null;
    state.lastPush = { at: 0, slot: null };
    afterChange();
  };
  handle.addEventListener('pointermove', move);
  handle.addEventListener('pointerup', up);
}

// ---- Start ------------------------------------------------------------------------------

async function start() {
  const { status, data } = await api('/api/file');
  if (status !== 200) {
    setState('clean', `Cannot load the file: ${data}`);
    return;
  }
  loaded(data);
  state.values = valuesOf(data.fields);
  state.tour = data.tour.slice();
  buildForm();
  renderTour();
  setState('clean', 'No unsaved changes');
  // The token is in the cookie now: keep it out of the address bar and the history.
  if (location.search) history.replaceState(null, '', '/');
  await runCheck();
  setTimeout(poll, POLL_MS);
}

document.addEventListener('DOMContentLoaded', () => {
  $('[data-action="save"]').addEventListener('click', save);
  $('[data-action="location-add"]').addEventListener('click', addLocation);
  $('[data-action="tour-add"]').addEventListener('click', () => {
    const id = Number($('#tour-add-id').value);
    if (id) changeTour(state.tour.concat([id]));
  });
  $('[data-action="undo"]').addEventListener('click', undo);
  $('[data-action="redo"]').addEventListener('click', redo);
  document.addEventListener('keydown', (event) => {
    const mod = event.ctrlKey || event.metaKey;
    if (!mod) return;
    const key = event.key.toLowerCase();
    if (key === 'z' && !event.shiftKey) { event.preventDefault(); undo(); }
    else if ((key === 'z' && event.shiftKey) || key === 'y') { event.preventDefault(); redo(); }
    else if (key === 's') { event.preventDefault(); save(); }
  });
  window.addEventListener('beforeunload', (event) => {
    if (state.base && (isDirty() || state.conflicts)) {
      event.preventDefault();
      event.returnValue = '';
    }
  });
  start();
});
