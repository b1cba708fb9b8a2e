// VRML97 (the paper's VRML 2.0, UTF-8 encoding) read into the scene of nodes.js, the same scene
// as X3D's: one builder and one event graph serve both formats. Fields of the nodes the page
// builds are read by their types; other nodes are read through, so that their DEF names are
// known, and not built. PROTOs are skipped, not expanded (the Java viewer expands them).
import {
    SceneDescription, SceneNode, ModelError, checkDepth, checkSize, coerce, fieldOf,
} from './nodes.js';
import { sceneModel } from './build.js';

const PUNCTUATION = new Set(['{', '}', '[', ']', '.']);
const WIDTH = { b: 1, f: 1, i: 1, s: 1, v3: 3, r: 4 };
const INTERFACE = new Set(['field', 'exposedField', 'eventIn', 'eventOut']);

/** The tokens of VRML97 text: numbers, strings, identifiers and punctuation, each with its line and column. */
function tokenize(text) {
    const tokens = [];
    let line = 1;
    let lineStart = 0;
    let i = 0;
    while (i < text.length) {
        const c = text[i];
        if (c === '\n') {
            line++;
            lineStart = ++i;
        } else if (c === ' ' || c === '\t' || c === '\r' || c === ',') {
            i++;
        } else if (c === '#') {
            while (i < text.length && text[i] !== '\n') {
                i++;
            }
        } else {
            const at = { line, column: i - lineStart + 1 };
            if (c === '"') {
                let value = '';
                i++;
                while (i < text.length && text[i] !== '"') {
                    if (text[i] === '\\' && i + 1 < text.length) {
                        i++;
                    }
                    if (text[i] === '\n') {
                        line++;
                        lineStart = i + 1;
                    }
                    value += text[i++];
                }
                if (i >= text.length) {
                    throw new ModelError(`line ${at.line}:${at.column}: a string is not closed`);
                }
                i++;
                tokens.push({ kind: 'string', value, ...at });
            } else if (PUNCTUATION.has(c) && !(c === '.' && /[0-9]/.test(text[i + 1] ?? ''))) {
                tokens.push({ kind: c, value: c, ...at });
                i++;
            } else {
                const start = i;
                while (i < text.length && !/[\s,"#{}[\]]/.test(text[i])
                        && !(text[i] === '.' && !/^[-+0-9.]/.test(text.slice(start, i + 1)))) {
                    i++;
                }
                const word = text.slice(start, i);
                const number = /^[-+]?(0x[0-9a-f]+|(\d+\.?\d*|\.\d+)(e[-+]?\d+)?)$/i.test(word) ? Number(word) : NaN;
                tokens.push(Number.isNaN(number) ? { kind: 'id', value: word, ...at }
                    : { kind: 'number', value: number, ...at });
            }
        }
    }
    return tokens;
}

class Parser {
    constructor(tokens) {
        this.tokens = tokens;
        this.at = 0;
        this.scene = new SceneDescription();
    }

    peek(ahead = 0) {
        return this.tokens[this.at + ahead];
    }

    where(token = this.peek()) {
        return token ? `line ${token.line}:${token.column}` : 'at the end';
    }

    next(expected) {
        const token = this.tokens[this.at];
        if (!token) {
            throw new ModelError(`the file ends where ${expected} was expected`);
        }
        this.at++;
        return token;
    }

    expect(kind, what) {
        const token = this.next(what);
        if (token.kind !== kind) {
            throw new ModelError(`${this.where(token)}: expected ${what}, found '${token.value}'`);
        }
        return token;
    }

    /** Statements until the end or a closing bracket: nodes, ROUTEs and skipped PROTOs. */
    statements(closing, depth) {
        const nodes = [];
        while (this.peek() && this.peek().kind !== closing) {
            const node = this.statement(depth);
            if (node) {
                nodes.push(node);
            }
        }
        return nodes;
    }

    statement(depth) {
        const token = this.peek();
        if (token.kind === 'id' && token.value === 'ROUTE') {
            this.route();
            return null;
        }
        if (token.kind === 'id' && (token.value === 'PROTO' || token.value === 'EXTERNPROTO')) {
            this.skipProto();
            return null;
        }
        return this.node(depth);
    }

    route() {
        const where = this.where();
        this.next('ROUTE');
        const fromNode = this.expect('id', 'a node name').value;
        this.expect('.', "'.'");
        const fromField = this.expect('id', 'a field name').value;
        const to = this.expect('id', 'TO');
        if (to.value !== 'TO') {
            throw new ModelError(`${this.where(to)}: expected TO, found '${to.value}'`);
        }
        const toNode = this.expect('id', 'a node name').value;
        this.expect('.', "'.'");
        const toField = this.expect('id', 'a field name').value;
        this.scene.routes.push({ fromNode, fromField, toNode, toField, where });
    }

    skipProto() {
        const proto = this.next('PROTO').value;
        this.expect('id', 'a PROTO name');
        this.skipBalanced('[', ']');
        if (proto === 'PROTO') {
            this.skipBalanced('{', '}');
        } else if (this.peek()?.kind === '[') {
            this.skipBalanced('[', ']');
        } else {
            this.expect('string', 'the EXTERNPROTO URL');
        }
    }

    skipBalanced(open, close) {
        this.expect(open, `'${open}'`);
        let depth = 1;
        while (depth > 0) {
            const token = this.next(`'${close}'`);
            depth += token.kind === open ? 1 : token.kind === close ? -1 : 0;
        }
    }

    /** A node: DEF name Type { fields }, USE name, or NULL (null). */
    node(depth) {
        const start = this.next('a node');
        const where = this.where(start);
        checkDepth(depth, where);
        if (start.kind !== 'id') {
            throw new ModelError(`${where}: expected a node, found '${start.value}'`);
        }
        if (start.value === 'NULL') {
            return null;
        }
        if (start.value === 'USE') {
            const name = this.expect('id', 'a DEF name').value;
            const used = this.scene.defs.get(name);
            if (!used) {
                throw new ModelError(`${where}: USE ${name} names no node DEF'd before it`);
            }
            this.scene.counted(where);
            return used;
        }
        let def = null;
        let type = start;
        if (start.value === 'DEF') {
            def = this.expect('id', 'a DEF name').value;
            type = this.expect('id', 'a node type');
        }
        const node = new SceneNode(type.value, def, where);
        this.scene.counted(where);
        this.expect('{', `'{' after ${type.value}`);
        while (this.peek()?.kind !== '}') {
            this.field(node, depth);
        }
        this.next('}');
        if (def) {
            this.scene.defs.set(def, node);
        }
        return node;
    }

    field(node, depth) {
        const name = this.expect('id', `a field of ${node.type} or '}'`);
        if (name.value === 'ROUTE' || name.value === 'PROTO' || name.value === 'EXTERNPROTO') {
            this.at--;
            this.statement(depth);
            return;
        }
        if (INTERFACE.has(name.value)) {
            // A Script's or prototype's own field: its type and name, and a value for fields.
            this.expect('id', 'a field type');
            this.expect('id', 'a field name');
            if (name.value === 'field' || name.value === 'exposedField') {
                this.anyValue(node, depth);
            }
            return;
        }
        const field = fieldOf(node.type, name.value);
        if (!field) {
            const values = this.anyValue(node, depth);
            if (values.nodes.length > 0) {
                node.fields.set(name.value, values.nodes);
            }
            return;
        }
        const kind = field[0];
        if (kind === 'n') {
            node.fields.set(name.value, this.node(depth + 1));
        } else if (kind === 'mn') {
            if (this.peek()?.kind === '[') {
                this.next('[');
                const nodes = this.statements(']', depth + 1);
                this.expect(']', "']'");
                node.fields.set(name.value, nodes);
            } else {
                node.fields.set(name.value, [this.node(depth + 1)].filter(Boolean));
            }
        } else {
            node.fields.set(name.value, coerce(node, name.value, this.words(kind), this.scene));
        }
    }

    /** The words of a value of a known type: as many as one value has, or a bracketed list. */
    words(kind) {
        const words = [];
        if (this.peek()?.kind === '[') {
            this.next('[');
            while (this.peek()?.kind !== ']') {
                words.push(this.word());
            }
            this.next(']');
            return words;
        }
        const width = WIDTH[kind] ?? WIDTH[kind.slice(1)] ?? (kind === 'mv2' ? 2 : 1);
        for (let i = 0; i < width; i++) {
            words.push(this.word());
        }
        return words;
    }

    word() {
        const token = this.next('a value');
        if (token.kind === 'number' || token.kind === 'string' || token.kind === 'id') {
            return token.value;
        }
        throw new ModelError(`${this.where(token)}: expected a value, found '${token.value}'`);
    }

    /** A value of a field the page does not know: its nodes are read (for their DEF names), the rest skipped. */
    anyValue(node, depth) {
        const nodes = [];
        const one = () => {
            const token = this.peek();
            const startsNode = token?.kind === 'id' && (token.value === 'DEF' || token.value === 'USE'
                || this.peek(1)?.kind === '{');
            if (startsNode) {
                const child = this.node(depth + 1);
                if (child) {
                    nodes.push(child);
                }
                return true;
            }
            if (token && (token.kind === 'number' || token.kind === 'string' || ['TRUE', 'FALSE', 'NULL']
                .includes(token.value))) {
                this.next('a value');
                return true;
            }
            return false;
        };
        if (this.peek()?.kind === '[') {
            this.next('[');
            while (this.peek()?.kind !== ']') {
                if (!one()) {
                    throw new ModelError(`${this.where()}: unexpected '${this.peek()?.value}' in a list`);
                }
            }
            this.next(']');
        } else {
            one();
            while (this.peek()?.kind === 'number') {
                this.next('a number');
            }
        }
        return { nodes };
    }
}

/** The scene of a VRML97 file, or a ModelError saying why it cannot be read. */
export function readVrml97(text) {
    checkSize(text, 'VRML97');
    if (!text.startsWith('#VRML V2.0 utf8')) {
        throw new ModelError(`VRML97 must start with '#VRML V2.0 utf8', starts with '${text.slice(0, 20)}'`);
    }
    const parser = new Parser(tokenize(text));
    parser.scene.roots = parser.statements(undefined, 1);
    return parser.scene;
}

/** The model of an agent that registered a VRML97 file. */
export async function loadVrml97(source, agent) {
    return sceneModel(readVrml97(source.text()), agent.name);
}
