// A model sent as a zip of its files ("format":"zip", protocol version 2, docs/protocol.md 6.2): a
// .gltf with its buffers and textures beside it, a .glb, or a VRML97 .wrl with its textures. The
// zip is unpacked in memory with fflate, which three.js ships; a file's references are looked up in
// the zip, relative to the file's folder, and handed to the loader as blob: URLs, so that nothing
// outside the zip is ever fetched. The server refused unsafe zips already; the limits are kept here
// too, for a page pointed at another server.
import * as THREE from './vendor/three/build/three.module.js';
import { unzipSync } from './vendor/three/examples/jsm/libs/fflate.module.js';
import { GLTFLoader } from './vendor/three/examples/jsm/loaders/GLTFLoader.js';
import { VRMLLoader } from './vendor/three/examples/jsm/loaders/VRMLLoader.js';

const MAX_BYTES = 4 * 1024 * 1024;
const MAX_ENTRIES = 256;
const MODEL = /\.(gltf|glb|x3d|wrl)$/i;

/** The zip's files by path, and the path of its model file: the one at the shallowest level that has one. */
export function unpack(zip) {
    let entries = 0;
    let total = 0;
    const files = unzipSync(zip, {
        filter(file) {
            if (++entries > MAX_ENTRIES) {
                throw new Error(`the zip has more than ${MAX_ENTRIES} entries`);
            }
            total += file.originalSize;
            if (total > MAX_BYTES) {
                throw new Error(`the zip's files unpack to more than ${MAX_BYTES} bytes (at '${file.name}')`);
            }
            return !file.name.endsWith('/');
        },
    });
    const models = Object.keys(files).filter(path => MODEL.test(path));
    const depth = path => path.split('/').length;
    const shallowest = Math.min(...models.map(depth));
    const top = models.filter(path => depth(path) === shallowest);
    if (top.length !== 1) {
        throw new Error(`the zip holds ${top.length} model files at its top (${top.join(', ')}), expected one`);
    }
    return { files, model: top[0] };
}

/** The path in the zip that a reference made in the file at `from` names, or null if it leaves the zip. */
export function resolve(from, uri) {
    let path;
    try {
        path = decodeURIComponent(uri);
    } catch {
        return null;
    }
    if (/^[A-Za-z][A-Za-z0-9+.-]*:/.test(path) || path.startsWith('/') || path.startsWith('\\')) {
        return null;
    }
    const segments = from.split('/').slice(0, -1);
    for (const segment of path.split('/')) {
        if (segment === '..') {
            if (segments.length === 0) {
                return null;
            }
            segments.pop();
        } else if (segment !== '.' && segment !== '') {
            segments.push(segment);
        }
    }
    return segments.join('/');
}

/** Loads the model of a zip: { object, clips }; throws, saying why, when it cannot. */
export async function loadZipped(zip) {
    const { files, model } = unpack(zip);
    const made = [];
    // Once the loaders have read every file: a VRML97 file's textures load after parse() returns.
    const manager = new THREE.LoadingManager(() => made.splice(0).forEach(url => URL.revokeObjectURL(url)));
    manager.setURLModifier(url => {
        if (url.startsWith('data:') || url.startsWith('blob:')) {
            return url;
        }
        const path = resolve(model, url);
        if (path === null || !(path in files)) {
            console.warn(`${model}: '${url}' is not a file of the model's zip; not loaded`);
            return 'data:,';
        }
        const blob = URL.createObjectURL(new Blob([files[path]]));
        made.push(blob);
        return blob;
    });
    const bytes = files[model];
    if (/\.glb$/i.test(model)) {
        const gltf = await new GLTFLoader(manager).parseAsync(bytes.buffer.slice(bytes.byteOffset,
            bytes.byteOffset + bytes.byteLength), '');
        return { object: gltf.scene, clips: gltf.animations };
    }
    if (/\.gltf$/i.test(model)) {
        const gltf = await new GLTFLoader(manager).parseAsync(new TextDecoder().decode(bytes), '');
        return { object: gltf.scene, clips: gltf.animations };
    }
    if (/\.wrl$/i.test(model)) {
        return { object: new VRMLLoader(manager).parse(new TextDecoder().decode(bytes), ''), clips: [] };
    }
    throw new Error(`${model}: this page does not draw a zipped ${model.slice(model.lastIndexOf('.'))} model`);
}
