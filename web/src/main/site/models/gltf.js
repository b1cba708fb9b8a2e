// glTF and glb, with three.js's GLTFLoader: the model with its animation clips, fitted to its
// agent as the Java viewer fits it (exports come in centimetres, with their origin at a corner or
// as tall as a house): everything under the node named after the agent (or under the root) is
// scaled to the body's height and stood on the ground, centred on the agent's place; that node is
// what walks and turns, in metres. Joints are the model's nodes of the registered names.
import * as THREE from '../vendor/three/build/three.module.js';
import { GLTFLoader } from '../vendor/three/examples/jsm/loaders/GLTFLoader.js';
import { SpatialRig } from './rigs.js';

/**
 * Fits `root` to `height`: the children of its node named `agent` (depth first; else of the root)
 * go into a group scaled so that their bounds, as authored, run from y = 0 to the height, centred
 * on x = z = 0. Returns the node that moves. A model with no extent is left as it is.
 */
export function fit(root, agent, height) {
    let moving = null;
    root.traverse(object => {
        if (!moving && object !== root && object.name === agent) {
            moving = object;
        }
    });
    moving ??= root;
    const fitted = new THREE.Group();
    fitted.name = `${agent} fitted`;
    [...moving.children].forEach(child => fitted.add(child));
    // Measured alone, at identity: the bounds in the moving node's own frame.
    fitted.updateMatrixWorld(true);
    const box = new THREE.Box3().setFromObject(fitted);
    moving.add(fitted);
    const tall = box.max.y - box.min.y;
    if (box.isEmpty() || !(tall > 0) || !Number.isFinite(tall)) {
        return moving;
    }
    // The moving node's own scale (an export's centimetres, often) stays; the fitted group undoes it.
    const own = moving.scale.y > 0 ? moving.scale.y : 1;
    const scale = height / (tall * own);
    const centre = box.getCenter(new THREE.Vector3());
    fitted.scale.setScalar(scale);
    fitted.position.set(-centre.x * scale, -box.min.y * scale, -centre.z * scale);
    return moving;
}

/**
 * The model of an agent that registered a glTF (JSON, buffers embedded) or glb file; `manager`
 * serves the files it refers to, when it came in a zip with them.
 */
export async function loadGltf(source, agent, manager = undefined) {
    const bytes = source.bytes();
    const gltf = await new GLTFLoader(manager).parseAsync(source.format === 'glb'
        ? bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) : new TextDecoder().decode(bytes), '');
    const moving = fit(gltf.scene, agent.name, agent.body.height);
    return { object: gltf.scene, rig: new SpatialRig(agent.name, gltf.scene, gltf.animations, moving) };
}
