// The studio's `generate` request from what a person types: a kind's options as KEY=VALUE words,
// as the command line's `datomsim generate KIND --KEY VALUE` takes them (docs/studio.md).

// What each kind of `generate` takes, as an example of its options (docs/studio.md).
export const GENERATE_EXAMPLES = {
  box: 'size=6,5,2 upright',
  arch: 'hole=2',
  random: 'count=100 seed=1 height=3',
  reshape: 'case=random floor=12,12 modules=20',
};

// "size=6,5,2 upright count=30": the request's fields, integers as numbers (a seed stays text:
// it may pass what a number holds exactly), true and false as such, a bare word as true.
export function generateFields(text) {
  const fields = {};
  for (const word of text.trim().split(/\s+/).filter(Boolean)) {
    const equals = word.indexOf('=');
    if (equals < 0) {
      fields[word] = true;
      continue;
    }
    const key = word.slice(0, equals);
    const value = word.slice(equals + 1);
    if (value === 'true' || value === 'false') fields[key] = value === 'true';
    else fields[key] = key !== 'seed' && /^-?\d+$/.test(value) ? Number(value) : value;
  }
  return fields;
}
