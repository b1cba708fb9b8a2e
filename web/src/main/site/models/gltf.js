// glTF and glb, with three.js's GLTFLoader: the model as its file has it, with its animation
// clips; joints are its nodes of the registered names.
import { GLTFLoader } from '../vendor/three/examples/jsm/loaders/GLTFLoader.js';
import { SpatialRig } from './rigs.js';

/** The model of an agent that registered a glTF (JSON, buffers embedded) or glb file. */
export async function loadGltf(source, agent) {
    const bytes = source.bytes();
    const gltf = await new GLTFLoader().parseAsync(source.format === 'glb' ? bytes.buffer
        : new TextDecoder().decode(bytes), '');
    return { object: gltf.scene, rig: new SpatialRig(agent.name, gltf.scene, gltf.animations) };
}
