// node validate.cjs VALIDATOR_DIR FILE.glb...: the Khronos glTF validator (npm package
// gltf-validator) on each file; prints each file's counts and every message, exits 1 when any
// file has an error or a warning (infos and hints are printed, and allowed).
const fs = require('fs');
const validator = require(process.argv[2]);
(async () => {
  let bad = 0;
  for (const file of process.argv.slice(3)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ` +
                `${i.numHints} hints`);
    for (const m of i.messages) console.log(`  ${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
    if (i.numErrors > 0 || i.numWarnings > 0) ++bad;
  }
  process.exit(bad ? 1 : 0);
})().catch((e) => {
  console.error(e);
  process.exit(1);
});
