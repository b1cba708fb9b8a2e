// An agent's model, by its format: one module a format, each a function from the model's source
// and the agent to the three.js object and the rig that drives it. A new format is one more module
// and one more line here.
import { loadBundled } from './bundled.js';
import { loadGltf } from './gltf.js';
import { placeholder } from './placeholder.js';
import { loadVrml97 } from './vrml97.js';
import { loadX3d } from './x3d.js';
import { loadZip } from './zip.js';

const FORMATS = new Map([
    ['gltf', loadGltf],
    ['glb', loadGltf],
    ['x3d', loadX3d],
    ['vrml97', loadVrml97],
    ['bundled', loadBundled],
    ['zip', loadZip],
]);

function bytes(base64) {
    const text = atob(base64);
    const out = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) {
        out[i] = text.charCodeAt(i);
    }
    return out;
}

/** What a loader reads: the format, the file's bytes or text, the bundled model's name. */
function source(model) {
    let decoded = null;
    const data = () => decoded ?? (decoded = bytes(model.data ?? ''));
    return { format: model.format, bundled: model.bundled, bytes: data, text: () => new TextDecoder().decode(data()) };
}

/**
 * The model of an agent (AgentState) as { object, rig }; a placeholder in `colour` when it sent
 * none, or when its model cannot be shown, saying why on the console.
 */
export async function loadModel(agent, colour) {
    const model = agent.model;
    const load = FORMATS.get(model?.format);
    if (!model) {
        return placeholder(agent, colour);
    }
    try {
        if (!load) {
            throw new Error(`the page reads no models of format '${model.format}'`);
        }
        return await load(source(model), agent);
    } catch (e) {
        console.warn(`agent ${agent.name}: its ${model.format} model cannot be shown, a placeholder stands in: ${
            e.message}`);
        return { ...placeholder(agent, colour), reason: e.message };
    }
}
