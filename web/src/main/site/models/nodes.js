// The VRML97 and X3D nodes the page builds, with their fields' types and defaults, and the scene
// both formats are read into: nodes with their fields, their DEF names and their ROUTEs. The X3D
// and VRML97 readers fill it; build.js turns it into three.js objects and an event graph. The same
// nodes, and the same limits, as the Java viewer's (docs/viewer.md).

/** How much of an untrusted model the page reads: as the Java viewer's limits. */
export const LIMITS = { bytes: 4 * 1024 * 1024, nodes: 20000, depth: 64, values: 1000000 };

/** A model that cannot be shown: malformed, over a limit, or unsafe; the message says why. */
export class ModelError extends Error {}

// Field types: b boolean, f number, i integer, v3 three numbers (a vector or a colour), r a
// rotation (axis and angle), s a string; m- the multiple-valued kinds, flat arrays; n one node,
// mn a list of nodes.
const GROUPING = { children: ['mn', []], bboxCenter: ['v3', [0, 0, 0]], bboxSize: ['v3', [-1, -1, -1]] };
const INTERPOLATOR = { key: ['mf', []] };

const TYPES = {
    Group: ['children', GROUPING],
    Collision: ['children', { ...GROUPING, collide: ['b', true], enabled: ['b', true], proxy: ['n', null] }],
    Anchor: ['children', { ...GROUPING, description: ['s', ''], url: ['ms', []], parameter: ['ms', []] }],
    Billboard: ['children', { ...GROUPING, axisOfRotation: ['v3', [0, 1, 0]] }],
    Transform: ['children', {
        ...GROUPING, center: ['v3', [0, 0, 0]], rotation: ['r', [0, 0, 1, 0]], scale: ['v3', [1, 1, 1]],
        scaleOrientation: ['r', [0, 0, 1, 0]], translation: ['v3', [0, 0, 0]],
    }],
    Switch: ['children', { ...GROUPING, choice: ['mn', []], whichChoice: ['i', -1] }],
    LOD: ['children', { ...GROUPING, level: ['mn', []], center: ['v3', [0, 0, 0]], range: ['mf', []] }],
    Shape: ['children', { appearance: ['n', null], geometry: ['n', null] }],
    Appearance: ['appearance', { material: ['n', null], texture: ['n', null], textureTransform: ['n', null] }],
    Material: ['material', {
        ambientIntensity: ['f', 0.2], diffuseColor: ['v3', [0.8, 0.8, 0.8]], emissiveColor: ['v3', [0, 0, 0]],
        shininess: ['f', 0.2], specularColor: ['v3', [0, 0, 0]], transparency: ['f', 0],
    }],
    ImageTexture: ['texture', { url: ['ms', []], repeatS: ['b', true], repeatT: ['b', true] }],
    Box: ['geometry', { size: ['v3', [2, 2, 2]] }],
    Sphere: ['geometry', { radius: ['f', 1] }],
    Cylinder: ['geometry', {
        bottom: ['b', true], height: ['f', 2], radius: ['f', 1], side: ['b', true], top: ['b', true],
    }],
    Cone: ['geometry', { bottomRadius: ['f', 1], height: ['f', 2], side: ['b', true], bottom: ['b', true] }],
    IndexedFaceSet: ['geometry', {
        color: ['n', null], coord: ['n', null], normal: ['n', null], texCoord: ['n', null], ccw: ['b', true],
        colorIndex: ['mi', []], colorPerVertex: ['b', true], convex: ['b', true], coordIndex: ['mi', []],
        creaseAngle: ['f', 0], normalIndex: ['mi', []], normalPerVertex: ['b', true], solid: ['b', true],
        texCoordIndex: ['mi', []],
    }],
    IndexedLineSet: ['geometry', {
        color: ['n', null], coord: ['n', null], colorIndex: ['mi', []], colorPerVertex: ['b', true],
        coordIndex: ['mi', []],
    }],
    Coordinate: ['coord', { point: ['mv3', []] }],
    Normal: ['normal', { vector: ['mv3', []] }],
    Color: ['color', { color: ['mv3', []] }],
    TextureCoordinate: ['texCoord', { point: ['mv2', []] }],
    TimeSensor: ['children', {
        cycleInterval: ['f', 1], enabled: ['b', true], loop: ['b', false], startTime: ['f', 0], stopTime: ['f', 0],
    }],
    PositionInterpolator: ['children', { ...INTERPOLATOR, keyValue: ['mv3', []] }],
    OrientationInterpolator: ['children', { ...INTERPOLATOR, keyValue: ['mr', []] }],
    ScalarInterpolator: ['children', { ...INTERPOLATOR, keyValue: ['mf', []] }],
};

const WIDTH = { v3: 3, r: 4, mv3: 3, mr: 4, mv2: 2 };

/** The field of that name of a node type: [kind, default], or undefined for one the page does not know. */
export function fieldOf(type, name) {
    return TYPES[type]?.[1][name];
}

/** Whether the page builds nodes of this type. */
export function known(type) {
    return Object.hasOwn(TYPES, type);
}

/** The field a child element fills in the XML encoding when it names none. */
export function containerField(type) {
    if (known(type)) {
        return TYPES[type][0];
    }
    return type.startsWith('Metadata') ? 'metadata' : 'children';
}

/**
 * The name of a field as a ROUTE names it, reduced to the field itself: `set_translation` and
 * `translation_changed` are the exposed field `translation`; events of their own (`set_fraction`,
 * `value_changed`, `fraction_changed`) stay as they are.
 */
export function routedField(type, name) {
    const base = name.startsWith('set_') ? name.slice(4) : name.endsWith('_changed') ? name.slice(0, -8) : name;
    return base !== name && fieldOf(type, base) ? base : name;
}

/** One node of a model: its type, its DEF name, its fields as read, and where it was read. */
export class SceneNode {
    constructor(type, def, where) {
        this.type = type;
        this.def = def;
        this.where = where;
        this.fields = new Map();
    }

    /** A field's value, or its default when the file left it out. */
    get(name) {
        if (this.fields.has(name)) {
            return this.fields.get(name);
        }
        const field = fieldOf(this.type, name);
        return field ? field[1] : undefined;
    }

    /** The nodes of a node field, as a list, whether it holds one node or many. */
    nodes(name) {
        const value = this.get(name);
        return value == null ? [] : Array.isArray(value) ? value : [value];
    }

    label() {
        return this.def ? `${this.type} '${this.def}'` : this.type;
    }
}

/** What a model file holds: its top nodes, its DEF names (a name defined twice means its later node), its ROUTEs. */
export class SceneDescription {
    constructor() {
        this.roots = [];
        this.defs = new Map();
        this.routes = [];
        this.count = 0;
        this.values = 0;
    }

    /** Counts a node against the limit, naming where the limit was passed. */
    counted(where) {
        if (++this.count > LIMITS.nodes) {
            throw new ModelError(`${where}: the model has more than ${LIMITS.nodes} nodes`);
        }
    }

    /** Counts numbers of a field's arrays against the limit. */
    countValues(n, where) {
        this.values += n;
        if (this.values > LIMITS.values) {
            throw new ModelError(`${where}: more than ${LIMITS.values} numbers in the model's arrays`);
        }
    }
}

/** Refuses a model too large or empty before it is read. */
export function checkSize(text, format) {
    if (text.length === 0) {
        throw new ModelError(`${format} model is empty`);
    }
    if (text.length > LIMITS.bytes) {
        throw new ModelError(`${format} model of ${text.length} characters is over the limit of ${LIMITS.bytes}`);
    }
}

/** Whether the nesting is still within the limit; throws naming where it is not. */
export function checkDepth(depth, where) {
    if (depth > LIMITS.depth) {
        throw new ModelError(`${where}: nesting deeper than ${LIMITS.depth} levels`);
    }
}

/**
 * A field's value from the words of a file (numbers, TRUE/FALSE or true/false, strings), checked
 * against its type: a number that is not one, or a vector of the wrong width, is an error naming
 * the field and the value.
 */
export function coerce(node, name, words, scene) {
    const field = fieldOf(node.type, name);
    const kind = field[0];
    const where = `${node.where}: ${node.label()} field ${name}`;
    if (kind === 'b') {
        const word = String(words[0]).toLowerCase();
        if (words.length !== 1 || (word !== 'true' && word !== 'false')) {
            throw new ModelError(`${where} must be TRUE or FALSE, was '${words.join(' ')}'`);
        }
        return word === 'true';
    }
    if (kind === 's') {
        return words.length > 0 ? String(words[0]) : '';
    }
    if (kind === 'ms') {
        return words.map(String);
    }
    const numbers = words.map(word => {
        const n = typeof word === 'number' ? word : Number(word);
        if (!Number.isFinite(n) || word === '') {
            throw new ModelError(`${where} must hold numbers, but has '${word}'`);
        }
        return n;
    });
    scene.countValues(numbers.length, where);
    if (kind === 'f' || kind === 'i') {
        if (numbers.length !== 1) {
            throw new ModelError(`${where} must be one number, has ${numbers.length}`);
        }
        return numbers[0];
    }
    const width = WIDTH[kind] ?? 1;
    if (kind.startsWith('m') ? numbers.length % width !== 0 : numbers.length !== width) {
        throw new ModelError(`${where} must hold ${kind.startsWith('m') ? 'a multiple of ' : ''}${width} numbers,`
            + ` has ${numbers.length}`);
    }
    return numbers;
}

/** Whether a field holds nodes (n, mn). */
export function holdsNodes(type, name) {
    const kind = fieldOf(type, name)?.[0];
    return kind === 'n' || kind === 'mn';
}
