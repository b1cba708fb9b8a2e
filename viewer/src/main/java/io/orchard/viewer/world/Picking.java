package io.orchard.viewer.world;

import io.orchard.protocol.value.Vec3;

/**
 * Which agent a ray from the eye hits, by the agents' bodies as the server models them: upright
 * cylinders of the body's radius and height standing where each agent is at the time shown.
 */
public final class Picking {

    private Picking() {
    }

    /**
     * The nearest agent hit by the ray from {@code (ox, oy, oz)} in direction {@code (dx, dy, dz)},
     * or null. Bodies are widened to at least {@code minRadius} so that small agents can be clicked.
     */
    public static AgentView pick(Iterable<AgentView> agents, double time, double ox, double oy, double oz,
                                 double dx, double dy, double dz, double minRadius) {
        AgentView best = null;
        double nearest = Double.POSITIVE_INFINITY;
        for (AgentView agent : agents) {
            Vec3 at = agent.positionAt(time);
            double radius = Math.max(minRadius, agent.body().radius());
            double hit = cylinderHit(ox, oy, oz, dx, dy, dz, at, radius, agent.body().height());
            if (hit < nearest) {
                nearest = hit;
                best = agent;
            }
        }
        return best;
    }

    /**
     * The distance along the ray (in units of the direction's length) to the first point of an
     * upright cylinder standing on {@code base}, or positive infinity when the ray misses it.
     */
    public static double cylinderHit(double ox, double oy, double oz, double dx, double dy, double dz, Vec3 base,
                                     double radius, double height) {
        double px = ox - base.x();
        double pz = oz - base.z();
        double a = dx * dx + dz * dz;
        double b = 2 * (px * dx + pz * dz);
        double c = px * px + pz * pz - radius * radius;
        double best = Double.POSITIVE_INFINITY;
        if (a > 1e-12) {
            double discriminant = b * b - 4 * a * c;
            if (discriminant >= 0) {
                double root = Math.sqrt(discriminant);
                for (double t : new double[] {(-b - root) / (2 * a), (-b + root) / (2 * a)}) {
                    double y = oy + t * dy - base.y();
                    if (t >= 0 && y >= 0 && y <= height && t < best) {
                        best = t;
                    }
                }
            }
        }
        if (Math.abs(dy) > 1e-12) {
            for (double capY : new double[] {base.y(), base.y() + height}) {
                double t = (capY - oy) / dy;
                double x = px + t * dx;
                double z = pz + t * dz;
                if (t >= 0 && x * x + z * z <= radius * radius && t < best) {
                    best = t;
                }
            }
        }
        return best;
    }
}
