// X3D's XML encoding, read with the browser's own XML parser into the scene of nodes.js. Nothing
// outside the text is read: a browser's DOMParser fetches no DTD and no external entity, and a
// document that declares entities (the "billion laughs") is refused before it is parsed.
import {
    SceneDescription, SceneNode, ModelError, checkDepth, checkSize, coerce, containerField, fieldOf, holdsNodes,
} from './nodes.js';
import { sceneModel } from './build.js';

const SKIPPED = new Set(['ProtoDeclare', 'ExternProtoDeclare', 'IS', 'connect', 'field', 'fieldValue']);
const NOT_FIELDS = new Set(['DEF', 'USE', 'containerField', 'class', 'id', 'style']);

/** The words of an attribute: numbers and booleans split at spaces and commas; quoted strings for MFString. */
function words(kind, text) {
    if (kind === 's') {
        return [text];
    }
    if (kind === 'ms') {
        const quoted = [...text.matchAll(/"((?:[^"\\]|\\.)*)"/g)].map(m => m[1].replace(/\\(.)/g, '$1'));
        return quoted.length > 0 || text.trim() === '' ? quoted : [text];
    }
    return text.split(/[\s,]+/).filter(word => word !== '');
}

class Reader {
    constructor() {
        this.scene = new SceneDescription();
        this.elements = 0;
    }

    where(element) {
        return `element ${this.elements} <${element.localName}>`;
    }

    /** The node an element stands for (a new one, or the one its USE names), or null for none. */
    node(element, depth) {
        this.elements++;
        const where = this.where(element);
        checkDepth(depth, where);
        const type = element.localName;
        const use = element.getAttribute('USE');
        if (use !== null) {
            const used = this.scene.defs.get(use);
            if (!used) {
                throw new ModelError(`${where}: USE '${use}' names no node DEF'd before it`);
            }
            this.scene.counted(where);
            return used;
        }
        const node = new SceneNode(type, element.getAttribute('DEF'), where);
        this.scene.counted(where);
        for (const attribute of element.attributes) {
            const field = fieldOf(type, attribute.name);
            if (!NOT_FIELDS.has(attribute.name) && field && !holdsNodes(type, attribute.name)) {
                node.fields.set(attribute.name, coerce(node, attribute.name, words(field[0], attribute.value),
                    this.scene));
            }
        }
        this.children(element, node, depth);
        // Registered once the element is read: a USE inside its own DEF cannot make a cycle.
        if (node.def) {
            this.scene.defs.set(node.def, node);
        }
        return node;
    }

    children(element, parent, depth) {
        for (const child of element.children) {
            if (SKIPPED.has(child.localName)) {
                continue;
            }
            if (child.localName === 'ROUTE') {
                this.route(child);
                continue;
            }
            const node = this.node(child, depth + 1);
            const field = child.getAttribute('containerField') ?? containerField(node.type);
            if (fieldOf(parent.type, field)?.[0] === 'n') {
                parent.fields.set(field, node);
            } else {
                // A list of nodes; under a node the page does not know, kept only so that DEF names inside are known.
                const list = parent.fields.get(field) ?? [];
                list.push(node);
                parent.fields.set(field, list);
            }
        }
    }

    route(element) {
        this.elements++;
        const route = {};
        for (const name of ['fromNode', 'fromField', 'toNode', 'toField']) {
            route[name] = element.getAttribute(name);
            if (!route[name]) {
                throw new ModelError(`${this.where(element)}: ROUTE without ${name}`);
            }
        }
        route.where = this.where(element);
        this.scene.routes.push(route);
    }
}

/** The scene of an X3D file (XML encoding), or a ModelError saying why it cannot be read. */
export function readX3d(text) {
    checkSize(text, 'X3D');
    if (/<!ENTITY/i.test(text)) {
        throw new ModelError('X3D declares entities (<!ENTITY ...>), which models may not use');
    }
    const document = new DOMParser().parseFromString(text, 'application/xml');
    const error = document.getElementsByTagName('parsererror')[0];
    if (error) {
        throw new ModelError(`X3D is not well-formed XML: ${error.textContent.trim().split('\n')[0]}`);
    }
    const root = document.documentElement;
    if (root.localName !== 'X3D') {
        throw new ModelError(`X3D's root element is <${root.localName}>, expected <X3D>`);
    }
    const scene = [...root.children].find(child => child.localName === 'Scene');
    if (!scene) {
        throw new ModelError('X3D has no <Scene>');
    }
    const reader = new Reader();
    const top = new SceneNode('Scene', null, 'Scene');
    reader.children(scene, top, 0);
    reader.scene.roots = top.nodes('children');
    return reader.scene;
}

/** The model of an agent that registered an X3D file. */
export async function loadX3d(source, agent) {
    return sceneModel(readX3d(source.text()), agent.name);
}
