// node validate-glb.js VALIDATOR_DIR FILE.glb: runs the Khronos glTF Validator (npm
// gltf-validator, installed by packaging/fetch-gltf-validator.sh) on FILE and prints its
// report's "issues" (numErrors, numWarnings, messages) as JSON on stdout.
const fs = require('fs');
const path = require('path');

const [validatorDir, file] = process.argv.slice(2);
const validator = require(path.resolve(validatorDir, 'node_modules', 'gltf-validator'));
validator
  .validateBytes(new Uint8Array(fs.readFileSync(file)), {maxIssues: 200, uri: path.basename(file)})
  .then((report) => console.log(JSON.stringify(report.issues)))
  .catch((error) => {
    console.error(`validate-glb: ${error}`);
    process.exit(1);
  });
