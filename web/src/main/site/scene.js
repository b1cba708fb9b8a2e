// The world's still parts, built from a WorldSnapshot: ground, river, bridges, castle, trees,
// tables and fruit, in the protocol's frame (y up, the ground the x/z plane), as the Java viewer
// draws them.
import * as THREE from './vendor/three/build/three.module.js';

export const COLOURS = {
    ground: 0x4f8a3a,
    river: 0x2a5fb0,
    bridge: 0x8a6a45,
    castle: 0xa8a29a,
    roof: 0x7d4a3a,
    trunk: 0x6b4a2b,
    crown: 0x2f6b2a,
    table: 0x9c7550,
    tomato: 0xd8321e,
    banana: 0xf2d431,
    coconut: 0x6e4b2a,
};

const FRUIT_RADIUS = { tomato: 0.15, banana: 0.25, coconut: 0.3 };

function material(colour) {
    return new THREE.MeshLambertMaterial({ color: colour });
}

function flatShape(points, y, colour) {
    const shape = new THREE.Shape(points.map(p => new THREE.Vector2(p.x, p.z)));
    const geometry = new THREE.ShapeGeometry(shape);
    // The shape is drawn in x/y; laid on the ground, its y becomes z.
    geometry.rotateX(Math.PI / 2);
    const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color: colour, side: THREE.DoubleSide }));
    mesh.position.y = y;
    return mesh;
}

function castle(shape) {
    const group = new THREE.Group();
    const outline = new THREE.Shape(shape.footprint.map(p => new THREE.Vector2(p.x, p.z)));
    const walls = new THREE.ExtrudeGeometry(outline, { depth: shape.height, bevelEnabled: false });
    // Extruded along +z from the x/y plane: turned so that it rises along +y with x/z kept.
    walls.rotateX(Math.PI / 2);
    walls.translate(0, shape.height, 0);
    group.add(new THREE.Mesh(walls, material(COLOURS.castle)));
    return group;
}

function bridge(b) {
    const dx = b.entryB.x - b.entryA.x;
    const dz = b.entryB.z - b.entryA.z;
    const length = Math.hypot(dx, dz);
    const deck = new THREE.Mesh(new THREE.BoxGeometry(b.width, 0.3, length), material(COLOURS.bridge));
    deck.position.set((b.entryA.x + b.entryB.x) / 2, 0.15, (b.entryA.z + b.entryB.z) / 2);
    deck.rotation.y = Math.atan2(dx, dz);
    return deck;
}

function tree(o) {
    const group = new THREE.Group();
    const trunkHeight = o.height * 0.45;
    const trunk = new THREE.Mesh(new THREE.CylinderGeometry(o.radius * 0.15, o.radius * 0.2, trunkHeight, 8),
        material(COLOURS.trunk));
    trunk.position.y = trunkHeight / 2;
    const crown = new THREE.Mesh(new THREE.ConeGeometry(o.radius, o.height - trunkHeight * 0.6, 10),
        material(COLOURS.crown));
    crown.position.y = trunkHeight * 0.4 + (o.height - trunkHeight * 0.6) / 2;
    group.add(trunk, crown);
    group.position.set(o.position.x, 0, o.position.z);
    return group;
}

function table(o) {
    const group = new THREE.Group();
    const top = new THREE.Mesh(new THREE.CylinderGeometry(o.radius, o.radius, 0.08, 20), material(COLOURS.table));
    top.position.y = o.height - 0.04;
    const leg = new THREE.Mesh(new THREE.CylinderGeometry(0.08, 0.1, o.height - 0.08, 8), material(COLOURS.table));
    leg.position.y = (o.height - 0.08) / 2;
    group.add(top, leg);
    group.position.set(o.position.x, 0, o.position.z);
    return group;
}

export function fruitMesh(f) {
    const radius = FRUIT_RADIUS[f.kind] ?? 0.2;
    const geometry = f.kind === 'banana'
        ? new THREE.CapsuleGeometry(radius * 0.45, radius * 1.6, 4, 8).rotateZ(Math.PI / 2.6)
        : new THREE.SphereGeometry(radius, 14, 10);
    const mesh = new THREE.Mesh(geometry, material(COLOURS[f.kind] ?? 0xffffff));
    mesh.position.set(f.position.x, f.position.y, f.position.z);
    mesh.name = f.id;
    mesh.userData.kind = f.kind;
    return mesh;
}

/** The still world and the fruit of a snapshot; fruit by id, to be taken away as it is eaten. */
export function buildWorld(snapshot) {
    const world = new THREE.Group();
    const b = snapshot.bounds;
    const ground = flatShape([{ x: b.minX, z: b.minZ }, { x: b.maxX, z: b.minZ }, { x: b.maxX, z: b.maxZ },
        { x: b.minX, z: b.maxZ }], 0, COLOURS.ground);
    world.add(ground);
    world.add(flatShape(snapshot.river.outline, 0.02, COLOURS.river));
    snapshot.bridges.forEach(x => world.add(bridge(x)));
    world.add(castle(snapshot.castle));
    for (const o of snapshot.obstacles) {
        world.add(o.kind === 'tree' ? tree(o) : table(o));
    }
    const fruit = new Map();
    for (const f of snapshot.fruit) {
        const mesh = fruitMesh(f);
        fruit.set(f.id, mesh);
        world.add(mesh);
    }
    return { world, fruit };
}
