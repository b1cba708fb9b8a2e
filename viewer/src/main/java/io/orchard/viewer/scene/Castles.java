package io.orchard.viewer.scene;

import com.jme3.math.FastMath;
import com.jme3.renderer.queue.RenderQueue.ShadowMode;
import com.jme3.scene.Geometry;
import com.jme3.scene.Node;
import com.jme3.scene.shape.Box;
import io.orchard.protocol.value.CastleShape;
import io.orchard.protocol.value.Point2;
import io.orchard.viewer.world.Polygons;
import java.util.ArrayList;
import java.util.List;

/**
 * The castle: its footprint extruded to the wall height, battlements along the top of every wall,
 * and a round tower with a pointed roof at each outer corner (the corners of the footprint's
 * convex hull, with corners close together sharing one tower).
 */
public final class Castles {

    private static final float MERLON_SPACING = 1.6f;
    private static final float MERLON_SIZE = 0.7f;

    private final Palette palette;

    /** Builds castles in the colours of {@code palette}. */
    public Castles(Palette palette) {
        this.palette = palette;
    }

    /** The castle's node. */
    public Node build(CastleShape castle) {
        Node node = new Node("castle");
        List<Point2> footprint = castle.footprint();
        float height = (float) castle.height();
        Geometry walls = new Geometry("castle walls", Meshes.prism(footprint, 0, height));
        walls.setMaterial(palette.lit(Palette.STONE));
        node.attachChild(walls);
        addBattlements(node, footprint, height);
        float towerRadius = towerRadius(footprint);
        for (Point2 corner : towerPlaces(footprint)) {
            Geometry tower = new Geometry("castle tower", Meshes.cylinder(towerRadius, towerRadius, height * 1.3f, 16));
            tower.setMaterial(palette.lit(Palette.DARK_STONE));
            tower.setLocalTranslation((float) corner.x(), 0, (float) corner.z());
            node.attachChild(tower);
            Geometry roof = new Geometry("castle roof", Meshes.cylinder(towerRadius * 1.2f, 0, towerRadius * 2.2f, 16));
            roof.setMaterial(palette.lit(Palette.ROOF));
            roof.setLocalTranslation((float) corner.x(), height * 1.3f, (float) corner.z());
            node.attachChild(roof);
        }
        node.setShadowMode(ShadowMode.CastAndReceive);
        return node;
    }

    /** Where towers stand: the hull's corners, those closer than a third of the castle's width merged. */
    static List<Point2> towerPlaces(List<Point2> footprint) {
        float merge = Math.max(2f, 0.3f * minExtent(footprint));
        List<List<Point2>> clusters = new ArrayList<>();
        for (Point2 corner : Polygons.convexHull(footprint)) {
            List<Point2> home = null;
            for (List<Point2> cluster : clusters) {
                if (centre(cluster).distance(corner) < merge) {
                    home = cluster;
                    break;
                }
            }
            if (home == null) {
                home = new ArrayList<>();
                clusters.add(home);
            }
            home.add(corner);
        }
        return clusters.stream().map(Castles::centre).toList();
    }

    private static float towerRadius(List<Point2> footprint) {
        return FastMath.clamp(0.12f * minExtent(footprint), 1f, 4f);
    }

    private static float minExtent(List<Point2> footprint) {
        double minX = Double.MAX_VALUE;
        double maxX = -Double.MAX_VALUE;
        double minZ = Double.MAX_VALUE;
        double maxZ = -Double.MAX_VALUE;
        for (Point2 p : footprint) {
            minX = Math.min(minX, p.x());
            maxX = Math.max(maxX, p.x());
            minZ = Math.min(minZ, p.z());
            maxZ = Math.max(maxZ, p.z());
        }
        return (float) Math.min(maxX - minX, maxZ - minZ);
    }

    private static Point2 centre(List<Point2> points) {
        double x = 0;
        double z = 0;
        for (Point2 p : points) {
            x += p.x();
            z += p.z();
        }
        return new Point2(x / points.size(), z / points.size());
    }

    private void addBattlements(Node node, List<Point2> footprint, float height) {
        int n = footprint.size();
        for (int i = 0; i < n; i++) {
            Point2 p = footprint.get(i);
            Point2 q = footprint.get((i + 1) % n);
            double length = p.distance(q);
            int count = (int) Math.floor(length / MERLON_SPACING);
            float angle = FastMath.atan2((float) (q.x() - p.x()), (float) (q.z() - p.z()));
            for (int k = 0; k < count; k++) {
                double t = (k + 0.5) / count;
                Geometry merlon = new Geometry("battlement", new Box(MERLON_SIZE / 2, MERLON_SIZE / 2, MERLON_SIZE / 2));
                merlon.setMaterial(palette.lit(Palette.DARK_STONE));
                merlon.setLocalTranslation((float) (p.x() + (q.x() - p.x()) * t), height + MERLON_SIZE / 2,
                        (float) (p.z() + (q.z() - p.z()) * t));
                merlon.rotate(0, angle, 0);
                node.attachChild(merlon);
            }
        }
    }
}
