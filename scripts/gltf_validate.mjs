// Runs the Khronos glTF Validator (npm gltf-validator) on each file named on the command line
// (after the validator's module path) and prints one line per file:
//   FILE<TAB>ERRORS<TAB>WARNINGS<TAB>CODES
// CODES: the distinct error codes, "-" when none. External resources (buffers, images) are read
// from beside the file. Used by scripts/gltf_validate.sh.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { createRequire } from 'node:module';

const [modulePath, ...files] = process.argv.slice(2);
const require = createRequire(import.meta.url);
const validator = require(modulePath);

for (const file of files) {
  let line;
  try {
    const data = await readFile(file);
    const report = await validator.validateBytes(new Uint8Array(data), {
      uri: path.basename(file),
      maxIssues: 1000,
      externalResourceFunction: (uri) =>
        readFile(path.join(path.dirname(file), decodeURIComponent(uri))).then(
          (b) => new Uint8Array(b)),
    });
    const codes = [...new Set(report.issues.messages.filter((m) => m.severity === 0)
                                          .map((m) => m.code))];
    line = [file, report.issues.numErrors, report.issues.numWarnings,
            codes.length ? codes.join(',') : '-'].join('\t');
  } catch (e) {
    line = [file, 1, 0, 'VALIDATOR_EXCEPTION:' + String(e).replace(/\s+/g, ' ')].join('\t');
  }
  console.log(line);
}
