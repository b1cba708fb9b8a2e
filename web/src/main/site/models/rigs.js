// How the server's messages reach a model, as the paper's applet drove the VRML browser: a walk,
// a turn, a joint's rotation, an animation started or stopped. Two kinds of model, two rigs: a
// three.js object moved as a whole (glTF, the placeholder), and an X3D or VRML97 scene driven
// through its own nodes and event graph.
import * as THREE from '../vendor/three/build/three.module.js';

/** A zero-length move still needs a positive cycle; this one ends within one frame. */
const SHORTEST_CYCLE = 1e-6;

/** A straight walk between two simulated times, placing `target` (a function of the point). */
class MoveTween {
    constructor(from, to, start, duration, target) {
        Object.assign(this, { from: from.clone(), to: to.clone(), start, duration, target, done: false });
    }

    apply(now) {
        if (this.done || now < this.start) {
            return;
        }
        const f = this.duration > 0 ? Math.min(1, (now - this.start) / this.duration) : 1;
        this.target(this.from.clone().lerp(this.to, f));
        this.done = f >= 1;
    }
}

/** The names a model has, for a message naming one it has not: reported once per name. */
class Unknown {
    constructor(agent) {
        this.agent = agent;
        this.told = new Set();
    }

    report(what, name, names) {
        if (!this.told.has(what + name)) {
            this.told.add(what + name);
            console.warn(`agent ${this.agent}: its model has no ${what} '${name}'; it has: ${[...names].join(', ')
                || 'none'}`);
        }
        return false;
    }
}

/**
 * A model moved as one object: walks and turns move its moving node (a glTF's node named after the
 * agent, else its root), joints are its nodes of those names, animations its glTF clips, played on
 * the game's clock.
 */
export class SpatialRig {
    constructor(agent, object, clips = [], moving = object) {
        this.object = object;
        this.moving = moving;
        this.unknown = new Unknown(agent);
        this.tween = null;
        this.last = null;
        this.mixer = clips.length > 0 ? new THREE.AnimationMixer(object) : null;
        this.actions = new Map(clips.map(clip => [clip.name, this.mixer.clipAction(clip)]));
    }

    moveTo(from, to, start, duration) {
        this.tween = new MoveTween(from, to, start, duration, p => this.moving.position.copy(p));
    }

    setRotation(q) {
        this.moving.quaternion.copy(q);
    }

    setJoint(name, q) {
        const joint = this.object.getObjectByName(name);
        if (!joint) {
            const names = [];
            this.object.traverse(o => o.name && o !== this.object && names.push(o.name));
            return this.unknown.report('joint', name, names);
        }
        joint.quaternion.copy(q);
        return true;
    }

    animation(name, start, loop) {
        const action = this.actions.get(name);
        if (!action) {
            return this.unknown.report('animation', name, this.actions.keys());
        }
        if (start) {
            action.setLoop(loop ? THREE.LoopRepeat : THREE.LoopOnce, Infinity).reset().play();
            action.clampWhenFinished = !loop;
        } else {
            action.stop();
        }
        return true;
    }

    update(time) {
        this.tween?.apply(time);
        // Clips play on simulated time: they stand still while the game is paused.
        if (this.mixer && this.last !== null && time > this.last) {
            this.mixer.update(time - this.last);
        }
        this.last = time;
    }
}

/**
 * An X3D or VRML97 model: walks go through the paper's <Name>Mover and <Name>TSMover when the
 * model has them ROUTEd to each other, otherwise to its Transform named after the agent (or its
 * root); turns to that Transform; joints are its DEF'd Transforms, animations its DEF'd
 * TimeSensors; its event graph steps on the game's clock.
 */
export class EventGraphRig {
    constructor(agent, built) {
        this.built = built;
        this.unknown = new Unknown(agent);
        this.agentTransform = built.transforms.get(agent) ?? null;
        const mover = built.interpolators.get(`${agent}Mover`);
        const clock = built.sensors.get(`${agent}TSMover`) ?? built.sensors.get(`${agent}TSMove`);
        const usable = mover && clock && mover.type === 'PositionInterpolator'
            && built.graph.isRouted(clock, 'fraction_changed', mover, 'set_fraction');
        this.mover = usable ? mover : null;
        this.moverClock = usable ? clock : null;
        this.tween = null;
    }

    moveTo(from, to, start, duration) {
        if (this.mover) {
            this.tween = null;
            const first = duration > 0 ? from : to;
            this.mover.setKeys([0, 1], [first.x, first.y, first.z, to.x, to.y, to.z]);
            this.moverClock.start(start, false, Math.max(duration, SHORTEST_CYCLE));
            return;
        }
        this.tween = new MoveTween(from, to, start, duration, this.agentTransform
            ? p => this.agentTransform.setTranslation(p) : p => this.built.object.position.copy(p));
    }

    setRotation(q) {
        if (this.agentTransform) {
            this.agentTransform.setRotation(q);
        } else {
            this.built.object.quaternion.copy(q);
        }
    }

    setJoint(name, q) {
        const joint = this.built.transforms.get(name);
        if (!joint) {
            return this.unknown.report('joint (DEF\'d Transform)', name, this.built.transforms.keys());
        }
        joint.setRotation(q);
        return true;
    }

    animation(name, start, loop, now) {
        const sensor = this.built.sensors.get(name);
        if (!sensor) {
            return this.unknown.report('animation (DEF\'d TimeSensor)', name, this.built.sensors.keys());
        }
        if (start) {
            sensor.start(now, loop, sensor.cycleInterval);
        } else {
            sensor.stop();
        }
        return true;
    }

    update(time) {
        this.built.graph.step(time);
        this.tween?.apply(time);
        if (this.tween?.done) {
            this.tween = null;
        }
    }
}
