// A model sent as a zip of its files ("format":"zip", protocol version 2, docs/protocol.md 6.2): a
// .gltf with its buffers and textures beside it, a .glb, an X3D or a VRML97 file. The zip is
// unpacked in memory with fflate, which three.js ships; a glTF's references are looked up in the
// zip, relative to the file's folder, and handed to the loader as blob: URLs, so that nothing
// outside the zip is ever fetched. X3D and VRML97 are read by the page's own readers, which draw
// materials, not textures. The server refused unsafe zips already; the limits are kept here too,
// for a page pointed at another server.
import * as THREE from '../vendor/three/build/three.module.js';
import { unzipSync } from '../vendor/three/examples/jsm/libs/fflate.module.js';
import { loadGltf } from './gltf.js';
import { ModelError } from './nodes.js';
import { loadVrml97 } from './vrml97.js';
import { loadX3d } from './x3d.js';

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
                throw new ModelError(`the zip has more than ${MAX_ENTRIES} entries`);
            }
            total += file.originalSize;
            if (total > MAX_BYTES) {
                throw new ModelError(`the zip's files unpack to more than ${MAX_BYTES} bytes (at '${file.name}')`);
            }
            return !file.name.endsWith('/');
        },
    });
    const models = Object.keys(files).filter(path => MODEL.test(path));
    const depth = path => path.split('/').length;
    const shallowest = Math.min(...models.map(depth));
    const top = models.filter(path => depth(path) === shallowest);
    if (top.length !== 1) {
        throw new ModelError(`the zip holds ${top.length} model files at its top (${top.join(', ')}), expected one`);
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

/** A loading manager that serves a file's references from the zip, as blob: URLs freed once all are read. */
function zipManager(files, model) {
    const made = [];
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
    return manager;
}

/** The model of an agent that registered a zip of its model's files. */
export async function loadZip(source, agent) {
    const { files, model } = unpack(source.bytes());
    const bytes = files[model];
    const extension = model.slice(model.lastIndexOf('.') + 1).toLowerCase();
    const inner = {
        format: extension === 'wrl' ? 'vrml97' : extension,
        bytes: () => bytes,
        text: () => new TextDecoder().decode(bytes),
    };
    switch (inner.format) {
        case 'gltf':
        case 'glb':
            return loadGltf(inner, agent, zipManager(files, model));
        case 'x3d':
            return loadX3d(inner, agent);
        default:
            return loadVrml97(inner, agent);
    }
}
