import assert from 'node:assert/strict';
import { describe, it } from 'node:test';
import { GENERATE_EXAMPLES, generateFields } from '../src/generate_fields.js';

describe("the studio's generate fields", () => {
  it('reads KEY=VALUE words, integers as numbers and a bare word as true', () => {
    assert.deepEqual(generateFields(' size=6,5,2   upright '), { size: '6,5,2', upright: true });
    assert.deepEqual(generateFields('count=30 height=-2 grid=12,12,6'), { count: 30, height: -2, grid: '12,12,6' });
    assert.deepEqual(generateFields('upright=false'), { upright: false });
    assert.deepEqual(generateFields(''), {});
  });

  it('keeps a seed as text, so that a large one is not rounded', () => {
    assert.deepEqual(generateFields('seed=18446744073709551615'), { seed: '18446744073709551615' });
  });

  it('leaves what is not an integer as text, for the studio to refuse with its message', () => {
    assert.deepEqual(generateFields('hole=2.5 count=ten'), { hole: '2.5', count: 'ten' });
  });

  it('has an example for every kind the studio makes', () => {
    assert.deepEqual(Object.keys(GENERATE_EXAMPLES), ['box', 'arch', 'random', 'reshape']);
  });
});
