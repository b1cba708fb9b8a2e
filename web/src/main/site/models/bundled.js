// The models the viewers ship (`{"format":"bundled","bundled":"figure"}`): the Java viewer's X3D
// files, served beside the page. Each is written for an agent named after it (Figure, Bunny); every
// DEF name that starts with that word is renamed after the agent, so that an agent Guppy has the
// Transform Guppy and the animation GuppyTSWalk, and its <Name>Size Transform is scaled to the
// body's height, as the Java viewer does.
import { loadX3d } from './x3d.js';

const NAMES = ['figure', 'bunny'];

/** The bundled X3D text fitted to one agent: DEF names renamed after it, scaled to its height. */
export function fit(text, model, agent, height) {
    const prefix = model[0].toUpperCase() + model.slice(1);
    const nominal = /<meta\s+name=['"]orchard-height['"]\s+content=['"]([0-9.]+)['"]/.exec(text);
    const scale = (nominal ? height / Number(nominal[1]) : 1).toFixed(4);
    const sized = text.replace(`DEF='${prefix}Size'`, `DEF='${prefix}Size' scale='${scale} ${scale} ${scale}'`);
    return sized.replace(/\b(DEF|USE|fromNode|toNode)=(['"])([A-Za-z][A-Za-z0-9_-]*)\2/g,
        (whole, attribute, quote, name) => name.startsWith(prefix)
            ? `${attribute}=${quote}${agent}${name.slice(prefix.length)}${quote}` : whole);
}

export async function loadBundled(source, agent) {
    if (!NAMES.includes(source.bundled)) {
        throw new Error(`there is no bundled model '${source.bundled}' (expected one of ${NAMES.join(', ')})`);
    }
    const response = await fetch(`bundled/${source.bundled}.x3d`);
    if (!response.ok) {
        throw new Error(`the bundled model ${source.bundled} could not be fetched: HTTP ${response.status}`);
    }
    const text = fit(await response.text(), source.bundled, agent.name, agent.body.height);
    return loadX3d({ format: 'x3d', text: () => text }, agent);
}
