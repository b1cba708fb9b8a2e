// Builds three.js objects and the event graph from the scene of an X3D or VRML97 model: grouping
// nodes become groups, Transforms groups whose matrix the event graph keeps, shapes meshes or
// lines, each named after its DEF name so that a joint (LeftKnee) is found by name. A node used in
// several places (USE) appears as several objects sharing their geometry and their live node:
// turning a USEd Transform turns every copy. TimeSensors, interpolators, and every Transform and
// Material become live nodes of the event graph, joined by the model's ROUTEs.
import * as THREE from '../vendor/three/build/three.module.js';
import { EventGraph, LiveInterpolator, LiveMaterial, LiveTimeSensor, LiveTransform } from './events.js';
import { LIMITS, ModelError, checkDepth, known, routedField } from './nodes.js';
import { EventGraphRig } from './rigs.js';

const GROUPS = new Set(['Group', 'Collision', 'Anchor', 'Billboard']);
/** Nodes about a world or a camera, not an agent's body: not drawn, without a warning. */
const ENVIRONMENT = new Set(['WorldInfo', 'Viewpoint', 'NavigationInfo', 'Background', 'Fog', 'DirectionalLight',
    'PointLight', 'SpotLight', 'Sound', 'AudioClip']);
const SEGMENTS = 24;

/** The faces of an IndexedFaceSet: a non-indexed geometry, a triangle fan a polygon, normals by creaseAngle. */
function faceSet(node) {
    const points = node.get('coord')?.get('point') ?? [];
    const index = node.get('coordIndex');
    const ccw = node.get('ccw');
    const polygons = [];
    let polygon = [];
    for (const i of [...index, -1]) {
        if (i < 0) {
            if (polygon.length >= 3) {
                polygons.push(ccw ? polygon : [...polygon].reverse());
            }
            polygon = [];
        } else if (3 * i + 2 < points.length) {
            polygon.push(i);
        } else {
            throw new ModelError(`${node.where}: ${node.label()} coordIndex ${i} is past its ${
                points.length / 3} points`);
        }
    }
    const point = i => new THREE.Vector3(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    // Newell's normal of each polygon, and the polygons around each point, for smooth corners.
    const normals = polygons.map(p => {
        const n = new THREE.Vector3();
        p.forEach((a, k) => {
            const u = point(a);
            const v = point(p[(k + 1) % p.length]);
            n.x += (u.y - v.y) * (u.z + v.z);
            n.y += (u.z - v.z) * (u.x + v.x);
            n.z += (u.x - v.x) * (u.y + v.y);
        });
        return n.normalize();
    });
    const around = new Map();
    polygons.forEach((p, f) => p.forEach(i => around.set(i, [...(around.get(i) ?? []), f])));
    const crease = Math.cos(node.get('creaseAngle'));
    const smooth = node.get('creaseAngle') > 0;
    const colours = colourOf(node, polygons);
    const position = [];
    const normal = [];
    const colour = [];
    polygons.forEach((p, f) => {
        const corner = (i, k) => {
            position.push(...point(i).toArray());
            let n = normals[f];
            if (smooth) {
                n = new THREE.Vector3();
                around.get(i).filter(g => normals[g].dot(normals[f]) >= crease).forEach(g => n.add(normals[g]));
                n.normalize();
            }
            normal.push(n.x, n.y, n.z);
            if (colours) {
                colour.push(...colours(f, k));
            }
        };
        for (let k = 1; k + 1 < p.length; k++) {
            corner(p[0], 0);
            corner(p[k], k);
            corner(p[k + 1], k + 1);
        }
    });
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(position, 3));
    geometry.setAttribute('normal', new THREE.Float32BufferAttribute(normal, 3));
    if (colours) {
        geometry.setAttribute('color', new THREE.Float32BufferAttribute(colour, 3));
    }
    return geometry;
}

/**
 * The colour of a polygon's corner from the node's Color, as VRML reads it: per vertex or per
 * face, through colorIndex or else coordIndex (per vertex) or the face's number (per face); null
 * without a Color.
 */
function colourOf(node, polygons) {
    const list = node.get('color')?.get('color');
    if (!list || list.length === 0) {
        return null;
    }
    const index = node.get('colorIndex');
    const perVertex = node.get('colorPerVertex');
    const srgb = i => {
        const c = new THREE.Color().setRGB(list[3 * i] ?? 1, list[3 * i + 1] ?? 1, list[3 * i + 2] ?? 1,
            THREE.SRGBColorSpace);
        return [c.r, c.g, c.b];
    };
    if (!perVertex) {
        return f => srgb(index.length > 0 ? index[f] : f);
    }
    if (index.length === 0) {
        return (f, k) => srgb(polygons[f][k]);
    }
    // colorIndex runs as coordIndex does, -1 between polygons.
    const byPolygon = [];
    let current = [];
    for (const i of index) {
        if (i < 0) {
            byPolygon.push(current);
            current = [];
        } else {
            current.push(i);
        }
    }
    byPolygon.push(current);
    return (f, k) => srgb(byPolygon[f]?.[k] ?? 0);
}

function lineSet(node) {
    const points = node.get('coord')?.get('point') ?? [];
    const position = [];
    let previous = -1;
    for (const i of node.get('coordIndex')) {
        if (i >= 0 && 3 * i + 2 >= points.length) {
            throw new ModelError(`${node.where}: ${node.label()} coordIndex ${i} is past its ${points.length / 3} points`);
        }
        if (i >= 0 && previous >= 0) {
            position.push(points[3 * previous], points[3 * previous + 1], points[3 * previous + 2], points[3 * i],
                points[3 * i + 1], points[3 * i + 2]);
        }
        previous = i;
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(position, 3));
    return geometry;
}

/** A primitive's geometry; the parts it leaves out (a cylinder's top, a cone's bottom) as groups not drawn. */
function primitive(node) {
    switch (node.type) {
        case 'Box': {
            const [x, y, z] = node.get('size');
            return { geometry: new THREE.BoxGeometry(x, y, z) };
        }
        case 'Sphere':
            return { geometry: new THREE.SphereGeometry(node.get('radius'), SEGMENTS, SEGMENTS / 2) };
        case 'Cylinder': {
            const r = node.get('radius');
            return { geometry: new THREE.CylinderGeometry(r, r, node.get('height'), SEGMENTS),
                parts: [node.get('side'), node.get('top'), node.get('bottom')] };
        }
        case 'Cone':
            return { geometry: new THREE.ConeGeometry(node.get('bottomRadius'), node.get('height'), SEGMENTS),
                parts: [node.get('side'), false, node.get('bottom')] };
        default:
            return null;
    }
}

class Builder {
    constructor(scene) {
        this.scene = scene;
        this.transforms = new Map();
        this.materials = new Map();
        this.geometries = new Map();
        this.objects = 0;
        this.warned = new Set();
    }

    live(node, make) {
        let live = this.transforms.get(node) ?? this.materials.get(node);
        if (!live) {
            live = make(node);
            (node.type === 'Transform' ? this.transforms : this.materials).set(node, live);
        }
        return live;
    }

    /** The object for a child node, or null for nodes that show nothing. */
    object(node, depth) {
        checkDepth(depth, `${node.where}: ${node.label()}`);
        if (++this.objects > LIMITS.nodes) {
            throw new ModelError(`${node.where}: the model makes more than ${LIMITS.nodes} objects (counting each USE)`);
        }
        const type = node.type;
        if (!known(type)) {
            if (!type.startsWith('Metadata') && !this.warned.has(type)) {
                this.warned.add(type);
                (ENVIRONMENT.has(type) ? console.info : console.warn)(`${node.where}: ${type} is not drawn: ${
                    ENVIRONMENT.has(type) ? 'it belongs to a world, not to an agent' : 'a node type the page does not build'}`);
            }
            return null;
        }
        let object = null;
        let children = [];
        if (type === 'Transform') {
            object = this.live(node, n => new LiveTransform(n)).newInstance();
            children = node.nodes('children');
        } else if (GROUPS.has(type)) {
            object = new THREE.Group();
            children = node.nodes('children');
        } else if (type === 'Switch' || type === 'LOD') {
            object = new THREE.Group();
            const choices = type === 'Switch' ? node.nodes(node.fields.has('choice') ? 'choice' : 'children')
                : node.nodes(node.fields.has('level') ? 'level' : 'children');
            const which = type === 'Switch' ? node.get('whichChoice') : 0;
            children = which >= 0 && which < choices.length ? [choices[which]] : [];
        } else if (type === 'Shape') {
            object = this.shape(node);
        }
        if (object) {
            if (node.def && !object.name) {
                object.name = node.def;
            }
            for (const child of children) {
                const built = this.object(child, depth + 1);
                if (built) {
                    object.add(built);
                }
            }
        }
        return object;
    }

    shape(node) {
        const geometryNode = node.get('geometry');
        if (!geometryNode) {
            return null;
        }
        const materialNode = node.get('appearance')?.get('material');
        const live = materialNode ? this.live(materialNode, n => new LiveMaterial(n)) : null;
        const lines = geometryNode.type === 'IndexedLineSet';
        let geometry = this.geometries.get(geometryNode);
        let parts = null;
        if (!geometry) {
            if (geometryNode.type === 'IndexedFaceSet') {
                geometry = faceSet(geometryNode);
            } else if (lines) {
                geometry = lineSet(geometryNode);
            } else {
                const made = primitive(geometryNode);
                if (!made) {
                    if (!this.warned.has(geometryNode.type)) {
                        this.warned.add(geometryNode.type);
                        console.warn(`${geometryNode.where}: ${geometryNode.type} inside Shape is not drawn: a geometry the page does not build`);
                    }
                    return null;
                }
                geometry = made.geometry;
                parts = made.parts;
            }
            geometry.userData.parts = parts;
            this.geometries.set(geometryNode, geometry);
        }
        parts = geometry.userData.parts;
        const vertexColors = geometry.hasAttribute('color');
        const doubleSided = geometryNode.type === 'IndexedFaceSet' && !geometryNode.get('solid');
        let material;
        if (live) {
            material = live.material(!lines, vertexColors);
            material.side = doubleSided ? THREE.DoubleSide : THREE.FrontSide;
        } else {
            // No Material: VRML draws the shape unlit, in white.
            material = lines ? new THREE.LineBasicMaterial({ vertexColors })
                : new THREE.MeshBasicMaterial({ vertexColors, side: doubleSided ? THREE.DoubleSide : THREE.FrontSide });
        }
        if (lines) {
            return new THREE.LineSegments(geometry, material);
        }
        if (parts && parts.some(part => !part)) {
            const drawn = geometry.clone();
            drawn.groups = geometry.groups.filter(group => parts[group.materialIndex]);
            return new THREE.Mesh(drawn, [material, material, material]);
        }
        return new THREE.Mesh(geometry, material);
    }
}

/**
 * The model's objects under a group named `rootName`, and its event graph with the DEF'd
 * Transforms, TimeSensors and interpolators by name; a ModelError when it cannot be built.
 */
export function buildScene(scene, rootName) {
    const builder = new Builder(scene);
    const root = new THREE.Group();
    root.name = rootName;
    for (const node of scene.roots) {
        const object = builder.object(node, 1);
        if (object) {
            root.add(object);
        }
    }
    const graph = new EventGraph();
    const live = new Map([...builder.transforms, ...builder.materials]);
    const visit = new Set();
    const all = [];
    const walk = node => {
        if (!node || visit.has(node)) {
            return;
        }
        visit.add(node);
        all.push(node);
        for (const value of node.fields.values()) {
            (Array.isArray(value) ? value : [value]).forEach(v => v?.fields && walk(v));
        }
    };
    scene.roots.forEach(walk);
    scene.defs.forEach(walk);
    try {
        for (const node of all) {
            if (node.type === 'TimeSensor') {
                const sensor = new LiveTimeSensor(node);
                graph.addSensor(sensor);
                live.set(node, sensor);
            } else if (node.type.endsWith('Interpolator') && known(node.type)) {
                live.set(node, new LiveInterpolator(node));
            } else if (node.type === 'Transform' && !live.has(node)) {
                live.set(node, builder.live(node, n => new LiveTransform(n)));
            } else if (node.type === 'Material' && !live.has(node)) {
                live.set(node, builder.live(node, n => new LiveMaterial(n)));
            }
        }
    } catch (e) {
        throw e instanceof ModelError ? e : new ModelError(e.message);
    }
    for (const route of scene.routes) {
        const fromNode = scene.defs.get(route.fromNode);
        const toNode = scene.defs.get(route.toNode);
        const from = live.get(fromNode);
        const to = live.get(toNode);
        if (!from || !to) {
            console.warn(`${route.where}: ROUTE from ${route.fromNode}.${route.fromField} to ${route.toNode}.${
                route.toField} has no effect in the page${!fromNode || !toNode ? ' (a node it names is not DEF\'d)' : ''}`);
            continue;
        }
        graph.addRoute(from, routedField(fromNode.type, route.fromField), to, routedField(toNode.type, route.toField));
    }
    const named = kind => new Map([...scene.defs].filter(([, node]) => live.get(node) instanceof kind)
        .map(([name, node]) => [name, live.get(node)]));
    return {
        object: root, graph, transforms: named(LiveTransform), sensors: named(LiveTimeSensor),
        interpolators: named(LiveInterpolator),
    };
}

/** An X3D or VRML97 agent's model from its scene: its objects, driven through its event graph. */
export function sceneModel(scene, agent) {
    const built = buildScene(scene, agent);
    return { object: built.object, rig: new EventGraphRig(agent, built) };
}
