// The agents: each its model (models/: glTF and glb with their clips, X3D and VRML97 with their
// event graphs, the bundled figures, or a placeholder in its colour), walking the moves the server
// tells, turning to its heading, turning its registered joints and playing its animations, on the
// game's simulated clock. Where each agent is and which way it faces is kept apart from the
// models, as the protocol says it, for following an agent and for what it sees.
import * as THREE from './vendor/three/build/three.module.js';
import { loadModel } from './models/index.js';
import { quaternion } from './models/events.js';

const PALETTE = [0xe6194b, 0x4363d8, 0xf58231, 0x911eb4, 0x42d4f4, 0xf032e6, 0xffffff, 0x000075, 0x9a6324,
    0x800000];

const vector = p => new THREE.Vector3(p.x, p.y ?? 0, p.z);

function rotation(r) {
    return quaternion([r.axis.x, r.axis.y, r.axis.z, r.angle]);
}

/** One agent as the protocol tells it: body, where it walks, its heading; and its model. */
class Agent {
    constructor(state, colour) {
        this.name = state.name;
        this.body = state.body;
        this.colour = colour;
        this.heading = state.heading;
        this.move = { from: vector(state.position), to: vector(state.position), start: 0, duration: 0 };
        this.root = new THREE.Group();
        this.root.name = `agent ${state.name}`;
        this.model = null;
        this.waiting = [];
    }

    /** Tells its model now, or once it is loaded: joints and animations heard while it loads are not lost. */
    tell(change) {
        if (this.model) {
            change(this.model.rig);
        } else {
            this.waiting.push(change);
        }
    }

    /** Where it is at simulated time `time`: along its last move. */
    positionAt(time) {
        const m = this.move;
        const f = m.duration > 0 ? Math.min(1, Math.max(0, (time - m.start) / m.duration)) : 1;
        return m.from.clone().lerp(m.to, f);
    }
}

export class Agents {
    constructor(scene) {
        this.scene = scene;
        this.byName = new Map();
        this.count = 0;
        this.now = 0;
    }

    async add(state) {
        this.remove(state.name);
        const agent = new Agent(state, PALETTE[this.count++ % PALETTE.length]);
        this.byName.set(state.name, agent);
        this.scene.add(agent.root);
        const model = await loadModel(state, agent.colour);
        if (this.byName.get(state.name) !== agent) {
            return agent;
        }
        agent.model = model;
        agent.root.add(model.object);
        const at = agent.positionAt(this.now);
        model.rig.moveTo(at, at, this.now, 0);
        model.rig.setRotation(rotation({ axis: { x: 0, y: 1, z: 0 }, angle: agent.heading }));
        // A move heard while the model loaded.
        if (agent.move.duration > 0) {
            model.rig.moveTo(agent.move.from, agent.move.to, agent.move.start, agent.move.duration);
        }
        agent.waiting.splice(0).forEach(change => change(model.rig));
        return agent;
    }

    remove(name) {
        const agent = this.byName.get(name);
        if (agent) {
            this.scene.remove(agent.root);
            this.byName.delete(name);
            // Its geometries and materials are its own: their GPU buffers go with it.
            agent.root.traverse(object => {
                object.geometry?.dispose();
                [object.material].flat().forEach(material => material?.dispose());
            });
        }
    }

    moved(m) {
        const agent = this.byName.get(m.agent);
        if (agent) {
            agent.move = { from: vector(m.from), to: vector(m.to), start: m.startTime, duration: m.duration };
            agent.model?.rig.moveTo(agent.move.from, agent.move.to, m.startTime, m.duration);
        }
    }

    rotated(m) {
        const agent = this.byName.get(m.agent);
        if (agent) {
            const a = m.rotation.axis;
            // A turn about the up axis is a heading; any other orientation keeps the heading it had.
            if (Math.abs(a.x) < 1e-9 && Math.abs(a.z) < 1e-9 && a.y !== 0) {
                agent.heading = Math.sign(a.y) * m.rotation.angle;
            }
            agent.tell(rig => rig.setRotation(rotation(m.rotation)));
        }
    }

    jointRotated(m) {
        this.byName.get(m.agent)?.tell(rig => rig.setJoint(m.joint, rotation(m.rotation)));
    }

    animation(m, start) {
        const now = this.now;
        this.byName.get(m.agent)?.tell(rig => rig.animation(m.timeSensor, start, m.loop, now));
    }

    /** Moves every model to simulated time `time`: walks, event graphs, clips. */
    update(time) {
        this.now = time;
        for (const agent of this.byName.values()) {
            agent.model?.rig.update(time);
        }
    }
}
