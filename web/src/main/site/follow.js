// Following one agent, as the Java viewer's follow mode: the camera behind and above it, looking
// the way it faces; a ring at its feet; its view cone on the ground, drawn from its body's Sight
// (range and field of view, turned with its heading); and a line from its eyes to everything it
// perceives at this moment (sight.js): orange to fruit, white to trees and tables, violet to other
// agents, each seen thing also ringed in the same colour.
import * as THREE from './vendor/three/build/three.module.js';
import { sighting } from './sight.js';

export const COLOURS = { cone: 0xffeb4d, edge: 0xffd933, fruit: 0xff7319, object: 0xf2f2f2, agent: 0xe633e6 };
const ARC = 64;

/** The cone's area and outline for a Sight, facing -z (heading 0) from the origin. */
function cone(sight) {
    const group = new THREE.Group();
    group.name = 'view cone';
    const allAround = sight.fieldOfView >= 2 * Math.PI - 1e-9;
    const outline = allAround ? [] : [new THREE.Vector3(0, 0, 0)];
    for (let i = 0; i <= ARC; i++) {
        const b = -sight.fieldOfView / 2 + sight.fieldOfView * i / ARC;
        outline.push(new THREE.Vector3(-Math.sin(b) * sight.range, 0, -Math.cos(b) * sight.range));
    }
    const fan = [];
    for (let i = 0; i < ARC; i++) {
        const a = outline[allAround ? i : i + 1];
        const b = outline[allAround ? i + 1 : i + 2];
        fan.push(0, 0, 0, b.x, 0, b.z, a.x, 0, a.z);
    }
    const area = new THREE.BufferGeometry();
    area.setAttribute('position', new THREE.Float32BufferAttribute(fan, 3));
    const fill = new THREE.Mesh(area, new THREE.MeshBasicMaterial({
        color: COLOURS.cone, transparent: true, opacity: 0.3, depthWrite: false, side: THREE.DoubleSide,
    }));
    fill.name = 'cone area';
    const edge = new THREE.LineLoop(new THREE.BufferGeometry().setFromPoints(outline),
        new THREE.LineBasicMaterial({ color: COLOURS.edge }));
    edge.name = 'cone edge';
    group.add(fill, edge);
    return group;
}

function ring(inner, outer, colour) {
    const mesh = new THREE.Mesh(new THREE.RingGeometry(inner, outer, 32).rotateX(-Math.PI / 2),
        new THREE.MeshBasicMaterial({ color: colour, side: THREE.DoubleSide }));
    return mesh;
}

/** Lines of one colour from the eye to each seen thing, refilled each frame. */
class Lines {
    constructor(colour, parent) {
        this.object = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: colour }));
        this.object.frustumCulled = false;
        this.colour = colour;
        this.marks = new THREE.Group();
        parent.add(this.object, this.marks);
    }

    show(eye, ends) {
        const points = [];
        for (const end of ends) {
            points.push(eye, end.at);
        }
        this.object.geometry.dispose();
        this.object.geometry = new THREE.BufferGeometry().setFromPoints(points);
        this.object.visible = points.length > 0;
        while (this.marks.children.length < ends.length) {
            this.marks.add(ring(0.9, 1, this.colour));
        }
        this.marks.children.forEach((mark, i) => {
            mark.visible = i < ends.length;
            if (mark.visible) {
                const { at, radius } = ends[i];
                mark.position.set(at.x, 0.08, at.z);
                mark.scale.setScalar(radius);
            }
        });
    }
}

export class Follow {
    constructor(scene) {
        this.group = new THREE.Group();
        this.group.name = 'following';
        this.group.visible = false;
        scene.add(this.group);
        this.cone = null;
        this.sight = null;
        this.feet = null;
        this.lines = {
            fruit: new Lines(COLOURS.fruit, this.group),
            object: new Lines(COLOURS.object, this.group),
            agent: new Lines(COLOURS.agent, this.group),
        };
        this.seen = { objects: [], agents: [], fruit: [] };
    }

    /** Draws nothing: no agent is followed. */
    clear() {
        this.group.visible = false;
        this.seen = { objects: [], agents: [], fruit: [] };
    }

    /**
     * Draws `agent`'s cone, ring and lines at simulated time `time`, in a world of `snapshot`, the
     * `agents` and the `fruit` ({ id, kind, position }) still there; returns what it perceives.
     */
    update(agent, time, snapshot, agents, fruit) {
        if (this.sight !== agent.body.sight || this.agent !== agent) {
            this.build(agent);
        }
        const at = agent.positionAt(time);
        this.cone.position.set(at.x, 0.12, at.z);
        this.cone.rotation.y = agent.heading;
        this.feet.position.set(at.x, 0.1, at.z);
        this.seen = sighting(snapshot, agents, fruit, agent, time);
        const eye = new THREE.Vector3(at.x, at.y + agent.body.height * 0.9, at.z);
        const v = (x, y, z) => new THREE.Vector3(x, y, z);
        this.lines.fruit.show(eye, this.seen.fruit.map(f => ({ at: v(f.position.x, f.position.y, f.position.z),
            radius: 0.4 })));
        this.lines.object.show(eye, this.seen.objects.map(o => ({
            at: v(o.position.x, Math.min(o.height, 2), o.position.z), radius: o.radius })));
        this.lines.agent.show(eye, this.seen.agents.map(other => {
            const p = other.positionAt(time);
            return { at: v(p.x, p.y + other.body.height * 0.6, p.z), radius: other.body.radius + 0.3 };
        }));
        this.group.visible = !this.hidden;
        return this.seen;
    }

    build(agent) {
        this.agent = agent;
        this.sight = agent.body.sight;
        if (this.cone) {
            this.group.remove(this.cone, this.feet);
        }
        this.cone = cone(agent.body.sight);
        this.feet = ring(agent.body.radius + 0.1, agent.body.radius + 0.3, COLOURS.edge);
        this.group.add(this.cone, this.feet);
    }

    /** The camera behind and above the agent, steep enough to look over the crowns, as the Java viewer's. */
    static chase(camera, agent, time) {
        const at = agent.positionAt(time);
        const centre = new THREE.Vector3(at.x, at.y + agent.body.height * 0.5, at.z);
        const facing = new THREE.Vector3(-Math.sin(agent.heading), 0, -Math.cos(agent.heading));
        const back = 5 + 3 * agent.body.height;
        camera.position.copy(centre).addScaledVector(facing, -back * 0.75);
        camera.position.y += back * 0.85;
        camera.lookAt(centre.addScaledVector(facing, back * 0.5));
    }
}
