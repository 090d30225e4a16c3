// Validates glTF/GLB files with the Khronos glTF-Validator and exits non-zero when any file has
// an error (or cannot be read). Each message is printed as
//   FILE: SEVERITY CODE at JSON_POINTER: MESSAGE
// and each file ends with a count line, so a CTest log says what is wrong and where.
//
// usage: node validate.mjs --validator DIR [--max-warnings N] FILE_OR_DIR...
//   --validator DIR   the folder that holds node_modules/gltf-validator (tools/validate-gltf/vendor:
//                     the pinned package, refreshed by tools/validate-gltf/install.sh)
//   FILE_OR_DIR       a .gltf/.glb file, or a directory searched recursively for them
//   --max-warnings N  also fail when a file has more than N warnings (default: warnings only reported)
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const severityNames = ['error', 'warning', 'info', 'hint'];

function usage(message) {
    console.error(`validate.mjs: ${message}`);
    console.error('usage: node validate.mjs --validator DIR [--max-warnings N] FILE_OR_DIR...');
    process.exit(2);
}

function parseArguments(argv) {
    const options = { validatorDir: null, maxWarnings: Infinity, inputs: [] };
    for (let i = 0; i < argv.length; ++i) {
        const argument = argv[i];
        if (argument === '--validator' || argument === '--max-warnings') {
            if (i + 1 >= argv.length) usage(`${argument} needs a value`);
            const value = argv[++i];
            if (argument === '--validator') options.validatorDir = value;
            else if (!/^\d+$/.test(value)) usage(`--max-warnings ${value}: not a count`);
            else options.maxWarnings = Number(value);
        } else if (argument.startsWith('--')) {
            usage(`unknown option ${argument}`);
        } else {
            options.inputs.push(argument);
        }
    }
    if (!options.validatorDir) usage('--validator DIR is required');
    if (options.inputs.length === 0) usage('no files given');
    return options;
}

function gltfFilesUnder(input) {
    let stat;
    try {
        stat = fs.statSync(input);
    } catch (error) {
        throw new Error(`${input}: cannot read (${error.code ?? error.message})`);
    }
    if (!stat.isDirectory()) return [input];
    const found = [];
    for (const entry of fs.readdirSync(input, { withFileTypes: true }).sort((a, b) => a.name.localeCompare(b.name))) {
        const child = path.join(input, entry.name);
        if (entry.isDirectory()) found.push(...gltfFilesUnder(child));
        else if (/\.(gltf|glb)$/i.test(entry.name)) found.push(child);
    }
    return found;
}

// External buffers and images are read relative to the file, as a loader would; a missing one
// is reported by the validator as an issue of the file that names it.
function externalResourceReader(file) {
    return (uri) => fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))
        .then((data) => new Uint8Array(data));
}

async function validateFile(validator, file) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(bytes, {
        uri: path.basename(file),
        maxIssues: 0, // 0 = unlimited: a capped list would hide errors behind warnings
        externalResourceFunction: externalResourceReader(file),
    });
    for (const message of report.issues.messages) {
        const where = message.pointer ?? (message.offset !== undefined ? `byte ${message.offset}` : '(file)');
        console.log(`${file}: ${severityNames[message.severity] ?? message.severity} ${message.code} at ${where}: ${message.message}`);
    }
    const { numErrors, numWarnings, numInfos, numHints } = report.issues;
    console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos, ${numHints} hints`);
    return { numErrors, numWarnings, numInfos, numHints };
}

async function main() {
    const options = parseArguments(process.argv.slice(2));
    const require = createRequire(path.join(path.resolve(options.validatorDir), 'package.json'));
    let validator;
    try {
        validator = require('gltf-validator');
    } catch (error) {
        console.error(`validate.mjs: no gltf-validator under ${options.validatorDir}/node_modules (tools/validate-gltf/install.sh vendors it): ${error.message}`);
        process.exit(2);
    }

    let files;
    try {
        files = options.inputs.flatMap(gltfFilesUnder);
    } catch (error) {
        console.error(`validate.mjs: ${error.message}`);
        process.exit(1);
    }
    if (files.length === 0) {
        console.error(`validate.mjs: no .gltf or .glb files in ${options.inputs.join(' ')}`);
        process.exit(1);
    }

    const totals = { numErrors: 0, numWarnings: 0, numInfos: 0, numHints: 0 };
    const failed = [];
    for (const file of files) {
        let counts;
        try {
            counts = await validateFile(validator, file);
        } catch (error) {
            // The validator rejects input it cannot even classify as glTF or GLB.
            console.log(`${file}: error: not validated: ${error}`);
            counts = { numErrors: 1, numWarnings: 0, numInfos: 0, numHints: 0 };
        }
        for (const key of Object.keys(totals)) totals[key] += counts[key];
        if (counts.numErrors > 0 || counts.numWarnings > options.maxWarnings) failed.push(file);
    }
    console.log(`validate.mjs: glTF-Validator ${validator.version()}: ${files.length} files, ` +
                `${totals.numErrors} errors, ${totals.numWarnings} warnings, ${totals.numInfos} infos, ${totals.numHints} hints`);
    if (failed.length > 0) {
        console.log(`validate.mjs: FAILED: ${failed.join(' ')}`);
        process.exit(1);
    }
}

await main();
