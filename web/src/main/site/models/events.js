// The VRML97 execution model, reduced to what agent models use, as the Java viewer runs it: at
// each step every TimeSensor sends its events, and each event travels along the ROUTEs from its
// field, maybe causing more, until none are left; one field sends at most one event a step, which
// ends loops of ROUTEs. Time is the game's simulated time, so that a paused game stands still.
import * as THREE from '../vendor/three/build/three.module.js';

/** A rotation from VRML's axis and angle; a zero axis is no rotation. */
export function quaternion(v, offset = 0) {
    const axis = new THREE.Vector3(v[offset], v[offset + 1], v[offset + 2]);
    const length = axis.length();
    return length < 1e-9 ? new THREE.Quaternion() : new THREE.Quaternion().setFromAxisAngle(axis.divideScalar(length),
        v[offset + 3]);
}

/** VRML's axis and angle of a rotation. */
function axisAngle(q) {
    const sin = Math.hypot(q.x, q.y, q.z);
    return sin < 1e-9 ? [0, 0, 1, 0] : [q.x / sin, q.y / sin, q.z / sin, 2 * Math.atan2(sin, q.w)];
}

export class EventGraph {
    constructor() {
        this.routes = new Map();
        this.sensors = [];
    }

    addSensor(sensor) {
        this.sensors.push(sensor);
    }

    addRoute(from, fromField, to, toField) {
        const key = `${fromField}`;
        const byField = this.routes.get(from) ?? new Map();
        this.routes.set(from, byField);
        const targets = byField.get(key) ?? [];
        byField.set(key, targets);
        targets.push({ node: to, field: toField });
    }

    isRouted(from, fromField, to, toField) {
        return (this.routes.get(from)?.get(fromField) ?? []).some(t => t.node === to && t.field === toField);
    }

    /** One time step at simulated time `now`, in seconds. */
    step(now) {
        const pending = [];
        const fired = new Map();
        const cascade = {
            now,
            emit(from, field, value) {
                const fields = fired.get(from) ?? new Set();
                fired.set(from, fields);
                if (!fields.has(field)) {
                    fields.add(field);
                    pending.push({ from, field, value });
                }
            },
        };
        for (const sensor of this.sensors) {
            sensor.tick(now, cascade);
        }
        for (let i = 0; i < pending.length; i++) {
            const event = pending[i];
            for (const target of this.routes.get(event.from)?.get(event.field) ?? []) {
                target.node.receive(target.field, event.value, cascade);
            }
        }
    }
}

/**
 * VRML counts time from 1970, so in a browser a one-shot sensor with startTime 0 finished long
 * before the page loaded; the game's clock starts at its start. Moving the file's times far into
 * the past keeps their meaning: one-shot sensors wait to be started, looping ones already run.
 */
const FILE_TIME_ORIGIN = -1e9;

/**
 * A running TimeSensor. As VRML97, with one addition: a sensor started by a message (a move, an
 * animation) always delivers its last event, even when the first step after its start is past
 * its end, so that a late message still lands where it should.
 */
export class LiveTimeSensor {
    constructor(node) {
        this.name = node.def;
        this.cycleInterval = node.get('cycleInterval');
        if (!(this.cycleInterval > 0)) {
            throw new Error(`${node.where}: ${node.label()} field cycleInterval must be positive but is ${
                this.cycleInterval}`);
        }
        this.enabled = node.get('enabled');
        this.loop = node.get('loop');
        this.startTime = node.get('startTime') + FILE_TIME_ORIGIN;
        this.stopTime = node.get('stopTime') + FILE_TIME_ORIGIN;
        this.active = false;
        this.explicitStart = false;
        this.cycleStart = 0;
    }

    /** Starts (or starts again) at `at`, looping or not, with this cycle and no stop time. */
    start(at, looping, interval) {
        Object.assign(this, { enabled: true, loop: looping, cycleInterval: interval, startTime: at, stopTime: 0,
            active: false, explicitStart: true });
    }

    stop() {
        this.enabled = false;
        this.explicitStart = false;
    }

    receive(field, value, cascade) {
        switch (field) {
            case 'enabled':
                this.enabled = value;
                if (!value && this.active) {
                    this.deactivate(cascade);
                }
                break;
            case 'loop':
                this.loop = value;
                break;
            case 'cycleInterval':
                if (!this.active && value > 0) {
                    this.cycleInterval = value;
                }
                break;
            case 'startTime':
                if (!this.active) {
                    this.startTime = value;
                }
                break;
            case 'stopTime':
                if (!this.active || value > this.startTime) {
                    this.stopTime = value;
                }
                break;
            default:
                return;
        }
        cascade.emit(this, field, value);
    }

    tick(now, cascade) {
        if (!this.enabled) {
            if (this.active) {
                this.deactivate(cascade);
            }
            return;
        }
        if (!this.active) {
            if (now < this.startTime) {
                return;
            }
            const end = this.end();
            if (now >= end) {
                if (this.explicitStart) {
                    this.explicitStart = false;
                    cascade.emit(this, 'fraction_changed', this.endFraction(end));
                    cascade.emit(this, 'time', now);
                }
                return;
            }
            this.active = true;
            this.explicitStart = false;
            this.cycleStart = this.startTime + Math.floor((now - this.startTime) / this.cycleInterval)
                * this.cycleInterval;
            cascade.emit(this, 'isActive', true);
            cascade.emit(this, 'cycleTime', now);
        }
        const end = this.end();
        if (now >= end) {
            cascade.emit(this, 'fraction_changed', this.endFraction(end));
            cascade.emit(this, 'time', now);
            this.deactivate(cascade);
            return;
        }
        const cycle = this.startTime + Math.floor((now - this.startTime) / this.cycleInterval) * this.cycleInterval;
        if (cycle > this.cycleStart) {
            this.cycleStart = cycle;
            cascade.emit(this, 'cycleTime', now);
        }
        cascade.emit(this, 'fraction_changed', this.fractionAt(now));
        cascade.emit(this, 'time', now);
    }

    end() {
        let end = this.loop ? Infinity : this.startTime + this.cycleInterval;
        if (this.stopTime > this.startTime) {
            end = Math.min(end, this.stopTime);
        }
        return end;
    }

    endFraction(end) {
        const stoppedEarly = this.stopTime > this.startTime
            && (this.loop || this.stopTime < this.startTime + this.cycleInterval);
        return stoppedEarly && end === this.stopTime ? this.fractionAt(end) : 1;
    }

    fractionAt(time) {
        const cycles = (time - this.startTime) / this.cycleInterval;
        const fraction = cycles - Math.floor(cycles);
        return fraction === 0 && time > this.startTime ? 1 : fraction;
    }

    deactivate(cascade) {
        this.active = false;
        cascade.emit(this, 'isActive', false);
    }
}

const COMPONENTS = { PositionInterpolator: 3, OrientationInterpolator: 4, ScalarInterpolator: 1 };

/**
 * A running Position-, Orientation- or ScalarInterpolator: on set_fraction it sends the value
 * between the key values around the fraction as value_changed, linear for positions and scalars,
 * along the shorter arc for rotations; before the first key and after the last, their values.
 */
export class LiveInterpolator {
    constructor(node) {
        this.name = node.def;
        this.type = node.type;
        this.components = COMPONENTS[node.type];
        this.setKeys(node.get('key'), node.get('keyValue'));
        if (this.keyValue.length !== this.key.length * this.components) {
            throw new Error(`${node.where}: ${node.label()} has ${this.key.length} keys but ${
                this.keyValue.length / this.components} key values; they must match`);
        }
        for (let i = 1; i < this.key.length; i++) {
            if (this.key[i] < this.key[i - 1]) {
                throw new Error(`${node.where}: ${node.label()} field key must not decrease, but ${this.key[i]} follows ${
                    this.key[i - 1]}`);
            }
        }
    }

    /** Replaces the keys, as the paper's applet did through the EAI before each move. */
    setKeys(key, keyValue) {
        this.key = [...key];
        this.keyValue = [...keyValue];
    }

    receive(field, value, cascade) {
        if (field === 'set_fraction') {
            const result = this.valueAt(value);
            if (result !== null) {
                cascade.emit(this, 'value_changed', result);
            }
        } else if (field === 'key' || field === 'keyValue') {
            this[field] = [...value];
            cascade.emit(this, field, value);
        }
    }

    valueAt(fraction) {
        const key = this.key;
        const c = this.components;
        const n = Math.min(key.length, Math.floor(this.keyValue.length / c));
        if (n === 0) {
            return null;
        }
        let i = 0;
        let t = 0;
        if (fraction >= key[n - 1]) {
            i = n - 1;
        } else if (fraction > key[0]) {
            while (i < n - 2 && fraction >= key[i + 1]) {
                i++;
            }
            const span = key[i + 1] - key[i];
            t = span > 0 ? (fraction - key[i]) / span : 0;
        }
        const j = Math.min(i + 1, n - 1);
        const v = this.keyValue;
        if (c === 4) {
            const a = quaternion(v, 4 * i);
            return axisAngle(t === 0 ? a : a.slerp(quaternion(v, 4 * j), t));
        }
        const out = [];
        for (let k = 0; k < c; k++) {
            out.push(v[c * i + k] + (v[c * j + k] - v[c * i + k]) * t);
        }
        return c === 1 ? out[0] : out;
    }
}

/**
 * A Transform at run time and the three.js objects that show it, one per place it appears (USE
 * adds a place), all kept equal. Its matrix is VRML's T·C·R·SR·S·SR⁻¹·C⁻¹, scale orientation
 * and centre included.
 */
export class LiveTransform {
    constructor(node) {
        this.name = node.def ?? '';
        this.instances = [];
        this.translation = new THREE.Vector3(...node.get('translation'));
        this.rotation = quaternion(node.get('rotation'));
        this.scale = new THREE.Vector3(...node.get('scale'));
        this.scaleOrientation = quaternion(node.get('scaleOrientation'));
        this.center = new THREE.Vector3(...node.get('center'));
    }

    /** The object for one more place the Transform appears. */
    newInstance() {
        const object = new THREE.Group();
        object.name = this.name;
        object.matrixAutoUpdate = false;
        this.instances.push(object);
        this.apply(object);
        return object;
    }

    setTranslation(v) {
        this.translation.copy(v);
        this.applyAll();
    }

    setRotation(q) {
        this.rotation.copy(q);
        this.applyAll();
    }

    receive(field, value, cascade) {
        switch (field) {
            case 'translation':
            case 'scale':
            case 'center':
                this[field].set(value[0], value[1], value[2]);
                break;
            case 'rotation':
            case 'scaleOrientation':
                this[field] = quaternion(value);
                break;
            default:
                return;
        }
        this.applyAll();
        cascade.emit(this, field, value);
    }

    applyAll() {
        this.instances.forEach(object => this.apply(object));
    }

    apply(object) {
        const m = new THREE.Matrix4().makeTranslation(this.translation.x + this.center.x,
            this.translation.y + this.center.y, this.translation.z + this.center.z);
        m.multiply(new THREE.Matrix4().makeRotationFromQuaternion(this.rotation));
        m.multiply(new THREE.Matrix4().makeRotationFromQuaternion(this.scaleOrientation));
        m.multiply(new THREE.Matrix4().makeScale(this.scale.x, this.scale.y, this.scale.z));
        m.multiply(new THREE.Matrix4().makeRotationFromQuaternion(this.scaleOrientation.clone().invert()));
        m.multiply(new THREE.Matrix4().makeTranslation(-this.center.x, -this.center.y, -this.center.z));
        object.matrix.copy(m);
        object.matrixWorldNeedsUpdate = true;
    }
}

/**
 * A Material at run time and the three.js material that shows it: VRML's lighting as Phong's,
 * diffuse, specular and emissive colours, shininess times 128, opacity 1 − transparency. A
 * material with only an emissive colour glows, unlit. ROUTEd changes reach every shape using it.
 */
export class LiveMaterial {
    constructor(node) {
        this.diffuse = node.get('diffuseColor');
        this.emissive = node.get('emissiveColor');
        this.specular = node.get('specularColor');
        this.shininess = node.get('shininess');
        this.transparency = node.get('transparency');
        this.materials = [];
    }

    selfLit() {
        const black = c => c[0] === 0 && c[1] === 0 && c[2] === 0;
        return black(this.diffuse) && black(this.specular) && !black(this.emissive);
    }

    /** The three.js material for a shape: lit faces, or unlit lines and glowing faces; white under vertex colours. */
    material(lit, vertexColors) {
        const material = lit && !this.selfLit() ? new THREE.MeshPhongMaterial() : lit ? new THREE.MeshBasicMaterial()
            : new THREE.LineBasicMaterial();
        material.vertexColors = vertexColors;
        material.userData.lit = lit && !this.selfLit();
        this.materials.push(material);
        this.apply(material);
        return material;
    }

    receive(field, value, cascade) {
        const key = { diffuseColor: 'diffuse', emissiveColor: 'emissive', specularColor: 'specular',
            shininess: 'shininess', transparency: 'transparency' }[field];
        if (!key) {
            return;
        }
        this[key] = value;
        this.materials.forEach(m => this.apply(m));
        cascade.emit(this, field, value);
    }

    apply(material) {
        const colour = c => new THREE.Color().setRGB(c[0], c[1], c[2], THREE.SRGBColorSpace);
        const white = new THREE.Color(1, 1, 1);
        if (material.userData.lit) {
            material.color = material.vertexColors ? white : colour(this.diffuse);
            material.emissive = colour(this.emissive);
            material.specular = colour(this.specular);
            material.shininess = Math.max(1, 128 * this.shininess);
        } else {
            material.color = material.vertexColors ? white : colour(this.selfLit() || material.isLineBasicMaterial
                ? this.emissive : this.diffuse);
        }
        material.opacity = 1 - Math.min(1, Math.max(0, this.transparency));
        material.transparent = material.opacity < 1;
    }
}
