// What an agent perceives, by the protocol's rules (its section 3.4), worked out by the page from
// what it knows, as the Java viewer does: a thing is seen when the ground distance between
// centres is at most the sight's range, it lies within half the field of view either side of the
// heading, and the line of sight does not cross the castle. The server also rounds its numbers; the
// page needs only which things are seen, so the two agree but for things exactly on an edge.

function cross(ax, az, bx, bz, px, pz) {
    return (bx - ax) * (pz - az) - (bz - az) * (px - ax);
}

function onSegment(ax, az, bx, bz, px, pz) {
    return Math.min(ax, bx) <= px && px <= Math.max(ax, bx) && Math.min(az, bz) <= pz && pz <= Math.max(az, bz);
}

/** Whether two closed segments share a point. */
function segmentsCross(ax, az, bx, bz, cx, cz, dx, dz) {
    const d1 = cross(cx, cz, dx, dz, ax, az);
    const d2 = cross(cx, cz, dx, dz, bx, bz);
    const d3 = cross(ax, az, bx, bz, cx, cz);
    const d4 = cross(ax, az, bx, bz, dx, dz);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
        return true;
    }
    return (d1 === 0 && onSegment(cx, cz, dx, dz, ax, az)) || (d2 === 0 && onSegment(cx, cz, dx, dz, bx, bz))
        || (d3 === 0 && onSegment(ax, az, bx, bz, cx, cz)) || (d4 === 0 && onSegment(ax, az, bx, bz, dx, dz));
}

function contains(polygon, x, z) {
    let inside = false;
    for (let i = 0, j = polygon.length - 1; i < polygon.length; j = i++) {
        const a = polygon[i];
        const b = polygon[j];
        if ((a.z > z) !== (b.z > z) && x < (b.x - a.x) * (z - a.z) / (b.z - a.z) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

/** Whether the segment from a to b crosses an edge of the polygon or runs inside it. */
function behind(polygon, ax, az, bx, bz) {
    for (let i = 0; i < polygon.length; i++) {
        const p = polygon[i];
        const q = polygon[(i + 1) % polygon.length];
        if (segmentsCross(ax, az, bx, bz, p.x, p.z, q.x, q.z)) {
            return true;
        }
    }
    return contains(polygon, (ax + bx) / 2, (az + bz) / 2);
}

/** The view cone of an agent at `eye` with this heading and Sight, past the castle's footprint. */
export function viewCone(castle, eye, heading, sight) {
    const facingX = -Math.sin(heading);
    const facingZ = -Math.cos(heading);
    const allAround = sight.fieldOfView >= 2 * Math.PI - 1e-9;
    const cosHalf = Math.cos(sight.fieldOfView / 2);
    return (x, z) => {
        const dx = x - eye.x;
        const dz = z - eye.z;
        const distance = Math.hypot(dx, dz);
        if (distance > sight.range) {
            return false;
        }
        if (distance > 1e-9 && !allAround && dx * facingX + dz * facingZ < cosHalf * distance) {
            return false;
        }
        return !behind(castle, eye.x, eye.z, x, z);
    };
}

/**
 * What `agent` perceives at simulated time `time`: the trees and tables, the other agents and the
 * fruit in its view cone. `fruit` is a list of { id, kind, position }.
 */
export function sighting(snapshot, agents, fruit, agent, time) {
    const eye = agent.positionAt(time);
    const sees = viewCone(snapshot.castle.footprint, eye, agent.heading, agent.body.sight);
    return {
        objects: snapshot.obstacles.filter(o => sees(o.position.x, o.position.z)),
        agents: agents.filter(other => other !== agent && (p => sees(p.x, p.z))(other.positionAt(time))),
        fruit: fruit.filter(f => sees(f.position.x, f.position.z)),
    };
}
