// Puts the page together for the jar: the page's own files from src/main/site, the bundled models
// (the Java viewer's own X3D files, one source for both viewers), and the parts of three.js it
// imports, copied from node_modules (installed by `npm ci` from package-lock.json) into
// vendor/ with their relative layout. The loaders import the bare name 'three', which a browser
// resolves only through an import map, an inline script the Content-Security-Policy forbids; so
// the copies import three.module.js by its path instead.
import { cpSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, relative } from 'node:path';

const out = process.argv[2];
if (!out) {
    console.error('usage: node build.mjs OUTPUT_FOLDER (expected the folder the page goes to)');
    process.exit(2);
}
cpSync('src/main/site', out, { recursive: true });
cpSync('../viewer/src/main/resources/io/orchard/viewer/bundled', join(out, 'bundled'), { recursive: true });

const three = 'node_modules/three';
const files = [
    'LICENSE',
    'build/three.module.js',
    'build/three.core.js',
    'examples/jsm/loaders/GLTFLoader.js',
    'examples/jsm/libs/fflate.module.js',
    'examples/jsm/utils/BufferGeometryUtils.js',
    'examples/jsm/utils/SkeletonUtils.js',
];
const module = join(out, 'vendor/three/build/three.module.js');
for (const file of files) {
    const target = join(out, 'vendor/three', file);
    mkdirSync(dirname(target), { recursive: true });
    let text = readFileSync(join(three, file), 'utf8');
    if (file.startsWith('examples/')) {
        const path = relative(dirname(target), module).split('\\').join('/');
        text = text.replaceAll(/from 'three'/g, `from '${path}'`);
    }
    writeFileSync(target, text);
}
// The list of the site's files, the only ones the server serves: a path not on it is not found,
// whatever it says.
const listed = readdirSync(out, { recursive: true, withFileTypes: true })
    .filter(entry => entry.isFile())
    .map(entry => relative(out, join(entry.parentPath ?? entry.path, entry.name)).split('\\').join('/'))
    .filter(path => path !== 'files.txt')
    .sort();
writeFileSync(join(out, 'files.txt'), listed.join('\n') + '\n');
console.log(`orchard-web: the page and ${files.length} files of three.js ${
    JSON.parse(readFileSync(join(three, 'package.json'), 'utf8')).version} in ${out}`);
