// The page: a viewer of the Orchard protocol over the server's WebSocket. It says Hello as a viewer,
// gets the WorldSnapshot and one AgentAdded per agent, then every change, and draws them; a person
// instructs the selected agent, and an operator (who typed the operator token, sent in the Hello)
// starts, pauses and resumes the game.
import * as THREE from './vendor/three/build/three.module.js';
import { buildWorld } from './scene.js';
import { Agents } from './agents.js';
import { Follow } from './follow.js';

const $ = id => document.getElementById(id);
const canvas = $('world');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
renderer.setPixelRatio(window.devicePixelRatio);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x87a9c9);
scene.add(new THREE.HemisphereLight(0xffffff, 0x445533, 1.6));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
sun.position.set(-60, 120, 80);
scene.add(sun);
const camera = new THREE.PerspectiveCamera(50, 1, 1, 1000);

const agents = new Agents(scene);
const following = new Follow(scene);
const state = {
    socket: null, seq: 0, world: null, snapshot: null, seen: '', fruit: new Map(), bounds: null, phase: 'connecting',
    tickRate: 20, time: 0, timeAt: performance.now(), selected: null, operator: false, ready: false, frames: 0,
};

function send(message) {
    if (state.socket?.readyState === WebSocket.OPEN) {
        message.seq = ++state.seq;
        state.socket.send(JSON.stringify(message));
        return message.seq;
    }
    return -1;
}

function connect(operatorToken, token) {
    state.socket?.close();
    if (state.world) {
        scene.remove(state.world);
    }
    for (const name of [...agents.byName.keys()]) {
        agents.remove(name);
    }
    state.ready = false;
    state.snapshot = null;
    state.operator = Boolean(operatorToken);
    const socket = new WebSocket(`${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/socket`);
    state.socket = socket;
    socket.onopen = () => {
        const hello = { type: 'Hello', protocolVersion: 2, role: 'viewer', client: 'orchard-web' };
        if (operatorToken) {
            hello.operatorToken = operatorToken;
        }
        if (token) {
            hello.token = token;
        }
        send(hello);
    };
    socket.onmessage = event => {
        if (socket === state.socket) {
            receive(JSON.parse(event.data));
        }
    };
    socket.onclose = event => {
        if (socket === state.socket) {
            setPhase(`disconnected${event.reason ? ': ' + event.reason : ''}`);
        }
    };
}

function setPhase(phase) {
    state.phase = phase;
    $('phase').textContent = phase;
}

function setTime(time) {
    state.time = time;
    state.timeAt = performance.now();
}

function scores(list) {
    $('scores').replaceChildren(...list.map(s => {
        const item = document.createElement('li');
        item.textContent = `${s.agent}: ${s.points} ${s.points === 1 ? 'point' : 'points'} (${s.fruit} fruit)`;
        return item;
    }));
}

function said(who, text) {
    const item = document.createElement('li');
    item.textContent = `${who}: ${text}`;
    $('said').append(item);
    item.scrollIntoView({ block: 'nearest' });
}

function listAgents() {
    $('agents').replaceChildren(...[...agents.byName.values()].map(agent => {
        const item = document.createElement('li');
        const swatch = document.createElement('span');
        swatch.className = 'swatch';
        swatch.style.background = `#${agent.colour.toString(16).padStart(6, '0')}`;
        item.append(swatch, agent.name);
        item.dataset.agent = agent.name;
        item.classList.toggle('selected', agent.name === state.selected);
        item.onclick = () => select(agent.name);
        return item;
    }));
}

function select(name) {
    state.selected = name;
    $('selected').textContent = name ?? 'no agent';
    listAgents();
}

const handlers = {
    Welcome(m) {
        state.bounds = m.bounds;
        state.tickRate = m.tickRate;
        setTime(0);
        setPhase(m.phase ?? 'waiting');
        aim();
    },
    WorldSnapshot(m) {
        const built = buildWorld(m);
        state.world = built.world;
        state.snapshot = m;
        state.fruit = built.fruit;
        scene.add(state.world);
        setTime(m.time);
        scores(m.scores);
        state.ready = true;
    },
    async AgentAdded(m) {
        await agents.add(m.agent);
        listAgents();
    },
    AgentRemoved(m) {
        agents.remove(m.agent);
        if (state.selected === m.agent) {
            select(null);
        }
        listAgents();
    },
    AgentMoved: m => agents.moved(m),
    AgentRotated: m => agents.rotated(m),
    JointRotated: m => agents.jointRotated(m),
    AnimationStarted: m => agents.animation(m, true),
    AnimationStopped: m => agents.animation(m, false),
    FruitRemoved(m) {
        const mesh = state.fruit.get(m.fruit);
        mesh?.parent?.remove(mesh);
        state.fruit.delete(m.fruit);
    },
    Tick(m) {
        setTime(m.time);
        if (state.phase !== 'running' && state.phase !== 'over') {
            setPhase('running');
        }
    },
    GameStarted: () => setPhase('running'),
    ScoreUpdate: m => scores(m.scores),
    Say: m => said(m.agent, m.text),
    GameOver(m) {
        setPhase(`over: ${m.reason}`);
        scores(m.ranking);
    },
    ActionResult(m) {
        if (!m.agent) {
            $('answer').textContent = `${m.action}: ${m.outcome}${m.reason ? ' (' + m.reason + ')' : ''}`;
            if (m.outcome === 'accepted') {
                const command = state.commands?.get(m.seq);
                setPhase(command === 'pause' ? 'paused' : 'running');
            }
        }
    },
    Error(m) {
        $('answer').textContent = `refused: ${m.code}${m.text ? ' — ' + m.text : ''}`;
    },
};

function receive(message) {
    const handler = handlers[message.type];
    if (handler) {
        handler(message);
    }
}

function control(command) {
    const seq = send({ type: 'GameControl', command });
    state.commands = state.commands ?? new Map();
    state.commands.set(seq, command);
}

/** The overview: the whole world from above its south edge, as the Java viewer starts. */
function aim() {
    const b = state.bounds ?? { minX: -100, maxX: 100, minZ: -100, maxZ: 100 };
    const cx = (b.minX + b.maxX) / 2;
    const cz = (b.minZ + b.maxZ) / 2;
    const span = Math.max(b.maxX - b.minX, b.maxZ - b.minZ);
    camera.position.set(cx, span * 0.55, cz + span * 0.6);
    camera.lookAt(cx, 0, cz + span * 0.02);
}

/** What the fruit still there is, for what an agent sees. */
function fruitList() {
    return [...state.fruit.values()].map(mesh => ({ id: mesh.name, kind: mesh.userData.kind, position: mesh.position }));
}

/** The followed agent's cone and what it perceives, the camera behind it; false when none is followed. */
function follow(time) {
    const agent = agents.byName.get(state.selected);
    if (!$('follow').checked || !agent || !state.snapshot) {
        following.clear();
        showSeen(null);
        return false;
    }
    Follow.chase(camera, agent, time);
    showSeen(following.update(agent, time, state.snapshot, [...agents.byName.values()], fruitList()));
    return true;
}

/** The panel's list of what the followed agent perceives, rewritten only when it changes. */
function showSeen(seen) {
    const lines = seen ? [
        ...seen.fruit.map(f => `${f.kind ?? 'fruit'} ${f.id}`),
        ...seen.objects.map(o => `${o.kind} ${o.id} at (${o.position.x.toFixed(0)}, ${o.position.z.toFixed(0)})`),
        ...seen.agents.map(a => `agent ${a.name}`),
    ] : [];
    // Not following differs from following an agent that perceives nothing: the list is hidden.
    const text = seen ? lines.join('\n') : null;
    if (text !== state.seen) {
        state.seen = text;
        $('seen').replaceChildren(...lines.map(line => Object.assign(document.createElement('li'), { textContent: line })));
        $('sees').hidden = !seen;
    }
}

function resize() {
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (canvas.width !== Math.floor(width * renderer.getPixelRatio())
            || canvas.height !== Math.floor(height * renderer.getPixelRatio())) {
        renderer.setSize(width, height, false);
        camera.aspect = width / height;
        camera.updateProjectionMatrix();
    }
}

/** The camera: behind the followed agent, where a test put it, or over the whole world. */
function place(time) {
    if (!follow(time)) {
        if (state.view) {
            const v = state.view;
            camera.position.set(v[0], v[1], v[2]);
            camera.lookAt(v[3], v[4], v[5]);
        } else {
            aim();
        }
    }
}

function frame(now) {
    // Simulated time runs on between ticks, never more than two ticks past the last one heard.
    const ahead = state.phase === 'running' ? Math.min((now - state.timeAt) / 1000, 2 / state.tickRate) : 0;
    const time = state.time + ahead;
    $('clock').textContent = `t = ${time.toFixed(1)} s`;
    agents.update(time);
    resize();
    place(time);
    renderer.render(scene, camera);
    state.frames++;
    requestAnimationFrame(frame);
}

// Clicking an agent selects it, as in the Java viewer; clicking elsewhere keeps the selection.
canvas.onclick = event => {
    const r = canvas.getBoundingClientRect();
    const pointer = new THREE.Vector2((event.clientX - r.left) / r.width * 2 - 1, 1 - (event.clientY - r.top) / r.height * 2);
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(pointer, camera);
    const roots = [...agents.byName.values()].map(agent => agent.root);
    const hit = raycaster.intersectObjects(roots, true)[0];
    if (hit) {
        let object = hit.object;
        while (object && !roots.includes(object)) {
            object = object.parent;
        }
        const agent = [...agents.byName.values()].find(a => a.root === object);
        if (agent) {
            select(agent.name);
        }
    }
};

$('instruct').onsubmit = event => {
    event.preventDefault();
    const text = $('instruction').value.trim();
    if (!state.selected) {
        $('answer').textContent = 'select an agent first';
    } else if (text) {
        send({ type: 'Instruction', agent: state.selected, text, from: 'browser' });
        said(`to ${state.selected}`, text);
        $('instruction').value = '';
    }
};
$('operator').onsubmit = event => {
    event.preventDefault();
    connect($('token').value, $('access').value);
};
$('start').onclick = () => control('start');
$('pause').onclick = () => control('pause');
$('resume').onclick = () => control('resume');

// For tests and benchmarks: where a point of the world is on the page, in CSS pixels, and how far
// the page has got.
window.orchard = {
    get ready() { return state.ready; },
    get phase() { return state.phase; },
    get frames() { return state.frames; },
    /** The simulated time of the last frame drawn. */
    get time() { return agents.now; },
    follow(name) {
        select(name);
        $('follow').checked = Boolean(name);
    },
    agents: () => [...agents.byName.keys()],
    /** Where the page has an agent now, with its heading and body height. */
    position(name) {
        const agent = agents.byName.get(name);
        const p = agent?.positionAt(agents.now);
        return p ? { x: p.x, y: p.y, z: p.z, heading: agent.heading, height: agent.body.height } : null;
    },
    /** How an agent's model is drawn: its format, or the placeholder and why. */
    model(name) {
        const model = agents.byName.get(name)?.model;
        return model ? { placeholder: Boolean(model.placeholder), reason: model.reason ?? null } : null;
    },
    /** What the followed agent perceives, by kind: fruit ids, obstacle positions, agent names. */
    seen() {
        const seen = following.seen;
        return { fruit: seen.fruit.map(f => f.id), objects: seen.objects.map(o => o.id),
            agents: seen.agents.map(a => a.name) };
    },
    /** Shows or hides what following draws (cone, ring, lines), for a test to see where it is drawn. */
    showFollowing(visible) {
        following.hidden = !visible;
        following.group.visible = visible && following.group.visible;
        renderer.render(scene, camera);
    },
    /** A fixed camera at (x, y, z) looking at (tx, ty, tz), as the Java viewer's --camera and --look-at; null for the overview. */
    view(at) {
        state.view = at;
        place(agents.now);
    },
    /** Draws the next frame at once, so that a test's screenshot shows the scene as it is now. */
    draw() {
        renderer.render(scene, camera);
    },
    /** Shows or hides an agent and draws the next frame at once, so that a test sees where it was drawn. */
    show(name, visible) {
        const agent = agents.byName.get(name);
        if (agent) {
            agent.root.visible = visible;
            renderer.render(scene, camera);
        }
        return Boolean(agent);
    },
    project(x, y, z) {
        const v = new THREE.Vector3(x, y, z).project(camera);
        const r = canvas.getBoundingClientRect();
        return { x: r.left + (v.x + 1) / 2 * r.width, y: r.top + (1 - v.y) / 2 * r.height };
    },
};

connect(null, null);
requestAnimationFrame(frame);
