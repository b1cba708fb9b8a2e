// The agents: each a model (its registered glTF or glb with its animations, its VRML97, or a
// figure in its colour) standing on the ground, walking the moves the server tells, turning to its
// heading and turning its registered joints.
import * as THREE from './vendor/three/build/three.module.js';
import { GLTFLoader } from './vendor/three/examples/jsm/loaders/GLTFLoader.js';
import { VRMLLoader } from './vendor/three/examples/jsm/loaders/VRMLLoader.js';
import { loadZipped } from './zipmodel.js';

const PALETTE = [0xe6194b, 0x4363d8, 0xf58231, 0x911eb4, 0x42d4f4, 0xf032e6, 0xffffff, 0x000075, 0x9a6324,
    0x800000];

function bytes(base64) {
    const text = atob(base64);
    const out = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) {
        out[i] = text.charCodeAt(i);
    }
    return out;
}

/** A figure the size of the agent's body, its nose to the front: bundled and X3D models, for now. */
function figure(body, colour) {
    const group = new THREE.Group();
    const paint = new THREE.MeshLambertMaterial({ color: colour });
    const radius = body.radius;
    const torso = new THREE.Mesh(new THREE.CylinderGeometry(radius * 0.8, radius, body.height * 0.75, 16), paint);
    torso.position.y = body.height * 0.375;
    const head = new THREE.Mesh(new THREE.SphereGeometry(radius * 0.7, 16, 12), paint);
    head.position.y = body.height * 0.75 + radius * 0.5;
    const nose = new THREE.Mesh(new THREE.ConeGeometry(radius * 0.25, radius * 0.8, 8),
        new THREE.MeshLambertMaterial({ color: 0x222222 }));
    // The model's front is -z, north, as heading 0 faces.
    nose.rotation.x = -Math.PI / 2;
    nose.position.set(0, head.position.y, -radius * 0.9);
    group.add(torso, head, nose);
    return group;
}

async function load(model, body, colour) {
    const format = model?.format;
    try {
        if (format === 'gltf' || format === 'glb') {
            const data = bytes(model.data);
            const gltf = await new GLTFLoader().parseAsync(format === 'glb' ? data.buffer
                : new TextDecoder().decode(data), '');
            return { object: gltf.scene, clips: gltf.animations };
        }
        if (format === 'zip') {
            return await loadZipped(bytes(model.data));
        }
        if (format === 'vrml97') {
            return { object: new VRMLLoader().parse(new TextDecoder().decode(bytes(model.data)), ''), clips: [] };
        }
    } catch (e) {
        console.warn(`model of format ${format} could not be read, drawing a figure instead:`, e);
    }
    return { object: figure(body, colour), clips: [] };
}

export class Agents {
    constructor(scene) {
        this.scene = scene;
        this.byName = new Map();
        this.count = 0;
    }

    async add(state) {
        this.remove(state.name);
        const colour = PALETTE[this.count++ % PALETTE.length];
        const root = new THREE.Group();
        root.name = state.name;
        root.position.set(state.position.x, state.position.y ?? 0, state.position.z);
        root.rotation.y = state.heading;
        const agent = { name: state.name, colour, root, body: state.body, move: null, mixer: null, actions: new Map() };
        this.byName.set(state.name, agent);
        this.scene.add(root);
        const { object, clips } = await load(state.model, state.body, colour);
        if (this.byName.get(state.name) !== agent) {
            return agent;
        }
        root.add(object);
        if (clips.length > 0) {
            agent.mixer = new THREE.AnimationMixer(object);
            clips.forEach(clip => agent.actions.set(clip.name, agent.mixer.clipAction(clip)));
        }
        return agent;
    }

    remove(name) {
        const agent = this.byName.get(name);
        if (agent) {
            this.scene.remove(agent.root);
            this.byName.delete(name);
        }
    }

    moved(m) {
        const agent = this.byName.get(m.agent);
        if (agent) {
            agent.move = { from: m.from, to: m.to, start: m.startTime, duration: m.duration };
        }
    }

    rotated(m) {
        const agent = this.byName.get(m.agent);
        if (agent) {
            const a = m.rotation.axis;
            agent.root.quaternion.setFromAxisAngle(new THREE.Vector3(a.x, a.y, a.z).normalize(), m.rotation.angle);
        }
    }

    jointRotated(m) {
        const joint = this.byName.get(m.agent)?.root.getObjectByName(m.joint);
        if (joint) {
            const a = m.rotation.axis;
            joint.quaternion.setFromAxisAngle(new THREE.Vector3(a.x, a.y, a.z).normalize(), m.rotation.angle);
        }
    }

    animation(m, start) {
        const action = this.byName.get(m.agent)?.actions.get(m.timeSensor);
        if (action) {
            if (start) {
                action.setLoop(m.loop ? THREE.LoopRepeat : THREE.LoopOnce, Infinity).reset().play();
            } else {
                action.stop();
            }
        }
    }

    /** Places every agent where its move has it at simulated time {@code time}; plays animations. */
    update(time, seconds) {
        for (const agent of this.byName.values()) {
            const m = agent.move;
            if (m) {
                const f = m.duration > 0 ? Math.min(1, Math.max(0, (time - m.start) / m.duration)) : 1;
                agent.root.position.set(m.from.x + (m.to.x - m.from.x) * f, m.from.y + (m.to.y - m.from.y) * f,
                    m.from.z + (m.to.z - m.from.z) * f);
            }
            agent.mixer?.update(seconds);
        }
    }
}
