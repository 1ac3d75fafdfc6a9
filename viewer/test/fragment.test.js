import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { formatFragment, parseFragment } from '../src/fragment.js';

describe('URL fragment', () => {
  it('reads the time, the view, the selected module, labels and video mode', () => {
    assert.deepEqual(parseFragment('#t=12.5&view=top&select=7&labels&video'), {
      t: 12.5,
      view: 'top',
      select: 7,
      labels: true,
      video: true,
    });
    assert.deepEqual(parseFragment('t=0&view=3d'), { t: 0, view: '3d' });
    assert.deepEqual(parseFragment('#shadows=off'), { shadows: false });
    assert.deepEqual(parseFragment('#shadows=on'), { shadows: true });
    assert.deepEqual(parseFragment(''), {});
  });

  it('ignores what it does not know or cannot read', () => {
    assert.deepEqual(parseFragment('#t=soon&view=side&select=-3&labels=1&colour=red&t='), {});
    assert.deepEqual(parseFragment('#t=Infinity'), {});
  });

  it('writes what it reads back', () => {
    const moment = { t: 4.1256, view: 'top', select: 12, labels: true, video: false };
    assert.equal(formatFragment(moment), '#t=4.126&view=top&select=12&labels');
    assert.deepEqual(parseFragment(formatFragment(moment)), { t: 4.126, view: 'top', select: 12, labels: true });
    assert.equal(formatFragment({}), '#t=0&view=3d');
    assert.equal(formatFragment({ t: 2, shadows: false, video: true }), '#t=2&view=3d&shadows=off&video');
  });
});
