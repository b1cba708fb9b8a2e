package io.orchard.agents.map;

import io.orchard.protocol.message.CastlePerceptionMessage;
import io.orchard.protocol.message.LandmarkPerceptionMessage;
import io.orchard.protocol.message.PerceptionMessage;
import io.orchard.protocol.value.Bounds;
import io.orchard.protocol.value.FruitKind;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.PerceivedAgent;
import io.orchard.protocol.value.PerceivedBridge;
import io.orchard.protocol.value.PerceivedFruit;
import io.orchard.protocol.value.PerceivedObject;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import io.orchard.protocol.value.Sight;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;

/**
 * What an agent knows of the world, built from its perceptions (map building). Perception gives
 * trees, tables, other agents, the river and the bridges relative to the agent (distance, and
 * bearing from its heading) and fruit absolute; the memory turns everything into world
 * coordinates with the agent's own position and heading from the same perception, and keeps it:
 *
 * <ul>
 *   <li>the trees and tables seen, placed from the nearest sighting ({@link #obstacles()});
 *   <li>the fruit seen and not known to be gone, and the fruit known to be gone from
 *       {@code FruitEaten} news ({@link #fruit()}, {@link #gone(String)});
 *   <li>the bridges and a model of the river band ({@link #bridges()}, {@link #river()});
 *   <li>an estimate of where the castle is, from its compass sectors ({@link #castle()});
 *   <li>which cells of the world have been looked at ({@link #coverage()});
 *   <li>where the agent has stood, ground known to be walkable ({@link #trail()});
 *   <li>what rejected moves taught ({@link #learned()});
 *   <li>the rules a person set, which hold until lifted ({@link #conduct()}).
 * </ul>
 *
 * <p>{@link #terrainVersion()} grows whenever something that changes where the agent can walk
 * changes, so that planners know when to plan again.
 *
 * <p>Not thread-safe: it belongs to the controller's thread.
 */
public final class WorldMemory {

    private static final double MAX_MARGIN = 0.6;

    private final Bounds bounds;
    private final double radius;
    private final Sight sight;
    private final Map<String, KnownObstacle> obstacles = new LinkedHashMap<>();
    private final Map<String, KnownFruit> fruit = new LinkedHashMap<>();
    private final Set<String> gone = new HashSet<>();
    private final Map<String, KnownBridge> bridges = new LinkedHashMap<>();
    private final Map<String, Double> bridgeAccuracy = new HashMap<>();
    private final RiverMap river = new RiverMap();
    private final CastleEstimate castle;
    private final Coverage coverage;
    private final Trail trail;
    private final List<LearnedBlock> learned = new ArrayList<>();
    private final Conduct conduct = new Conduct();
    private List<SeenAgent> agents = List.of();
    private Sector castleSector;
    private Point2 position;
    private double heading;
    private long tick = -1;
    private Point2 start;
    private final Map<FruitKind, Integer> collected = new EnumMap<>(FruitKind.class);
    private long terrainVersion;
    private long fruitVersion;
    private Point2 lastExcluded;
    private long riverVersionExcluded = -1;
    private long castleVersionSeen = -1;

    /**
     * An empty memory.
     *
     * @param bounds the world's bounds (from the server's welcome)
     * @param radius the agent's body radius
     * @param sight  the agent's sight, to know what it has looked at
     */
    public WorldMemory(Bounds bounds, double radius, Sight sight) {
        this.bounds = Objects.requireNonNull(bounds, "bounds");
        this.radius = radius;
        this.sight = Objects.requireNonNull(sight, "sight");
        this.castle = new CastleEstimate(bounds);
        this.coverage = new Coverage(bounds);
        this.coverage.exclude(conduct::forbids);
        this.trail = new Trail(bounds);
    }

    /** Where the agent stands before its first perception (from its registration). */
    public void placed(Point2 where, double towards) {
        this.position = where;
        this.heading = towards;
        trail.stood(where);
        if (start == null) {
            start = where;
        }
    }

    /** Where the agent was first placed or perceived itself in this game; null before. */
    public @Nullable Point2 start() {
        return start;
    }

    /**
     * Takes one tick's perception. The landmark and castle perceptions of the same tick may be
     * null when they did not come.
     */
    public void perceive(PerceptionMessage perception, @Nullable LandmarkPerceptionMessage landmarks,
                         @Nullable CastlePerceptionMessage castleSeen) {
        Point2 self = perception.position().onGround();
        double facing = perception.heading();
        position = self;
        heading = facing;
        if (start == null) {
            start = self;
        }
        tick = perception.tick();
        trail.stood(self);
        for (PerceivedObject object : perception.objects()) {
            remember(object, self, facing);
        }
        List<SeenAgent> seen = new ArrayList<>(perception.agents().size());
        for (PerceivedAgent agent : perception.agents()) {
            seen.add(new SeenAgent(agent.name(), Bearings.toWorld(self, facing, agent.at()),
                    Bearings.normalise(facing + agent.heading()), agent.radius(), tick));
        }
        agents = List.copyOf(seen);
        for (PerceivedFruit seenFruit : perception.fruit()) {
            remember(seenFruit);
        }
        if (landmarks != null) {
            for (PerceivedBridge bridge : landmarks.bridges()) {
                remember(bridge, self, facing);
            }
            if (landmarks.river() != null) {
                Point2 shore = Bearings.toWorld(self, facing, landmarks.river().nearest());
                double runs = Bearings.normalise(facing + landmarks.river().across());
                if (river.sighted(new ShoreSighting(self, shore, runs))) {
                    terrainVersion++;
                }
            }
        }
        if (castleSeen != null) {
            castleSector = castleSeen.sector();
            castle.observe(self, castleSeen.sector());
        }
        excludeCastle(self);
        coverage.look(self, facing, sight);
    }

    /** This agent collected a fruit of this kind: counted, to tell the person what it has collected. */
    public void collected(FruitKind kind) {
        collected.merge(kind, 1, Integer::sum);
    }

    /** The fruit this agent has collected, by kind; kinds it has not collected are left out. */
    public Map<FruitKind, Integer> collected() {
        return Collections.unmodifiableMap(collected);
    }

    /** The fruit was collected (by anyone): forget it for good. */
    public void fruitEaten(String fruitId) {
        gone.add(fruitId);
        if (fruit.remove(fruitId) != null) {
            fruitVersion++;
        }
    }

    /**
     * A move of this agent from {@code from} to {@code to} was rejected for {@code reason}: learn
     * from it. A known tree or table gets a wider margin; anything else becomes a
     * {@link LearnedBlock}; a refusal by the castle also narrows down where the castle is.
     *
     * @return what the move ran into
     */
    public Obstruction moveRejected(Point2 from, Point2 to, String reason) {
        Obstruction obstruction = Obstruction.of(reason);
        switch (obstruction) {
            case TREE, TABLE -> {
                KnownObstacle known = obstacles.get(Obstruction.objectId(reason));
                if (known != null) {
                    obstacles.put(known.id(), known.withMargin(Math.min(MAX_MARGIN, known.margin() + 0.15)));
                } else {
                    learned.add(new LearnedBlock(from, to, obstruction.name().toLowerCase(Locale.ROOT)
                            + " " + Obstruction.objectId(reason), radius));
                }
                terrainVersion++;
            }
            case CASTLE -> {
                castle.touched(from, to, radius);
                learned.add(new LearnedBlock(from, to, "the castle", radius));
                terrainVersion++;
            }
            case RIVER -> {
                learned.add(new LearnedBlock(from, to, "the river", radius));
                terrainVersion++;
            }
            default -> {
                // the edge is known from the bounds; other reasons teach nothing about the world
            }
        }
        return obstruction;
    }

    // ---- what is known ----------------------------------------------------------------------

    /** The world's bounds. */
    public Bounds bounds() {
        return bounds;
    }

    /** The agent's body radius. */
    public double radius() {
        return radius;
    }

    /** The agent's sight. */
    public Sight sight() {
        return sight;
    }

    /** Where the agent stood at its latest perception; null before it was placed. */
    public Point2 position() {
        return position;
    }

    /** The agent's heading at its latest perception. */
    public double heading() {
        return heading;
    }

    /** The tick of the latest perception; -1 before the first. */
    public long tick() {
        return tick;
    }

    /** The trees and tables seen so far. */
    public Collection<KnownObstacle> obstacles() {
        return Collections.unmodifiableCollection(obstacles.values());
    }

    /** A tree or table by id. */
    public Optional<KnownObstacle> obstacle(String id) {
        return Optional.ofNullable(obstacles.get(id));
    }

    /** The fruit seen and not known to be gone. */
    public Collection<KnownFruit> fruit() {
        return Collections.unmodifiableCollection(fruit.values());
    }

    /** A fruit by id, if it is known and not gone. */
    public Optional<KnownFruit> fruit(String id) {
        return Optional.ofNullable(fruit.get(id));
    }

    /** Whether the fruit is known to have been collected. */
    public boolean gone(String fruitId) {
        return gone.contains(fruitId);
    }

    /** The other agents of the latest perception. */
    public List<SeenAgent> agents() {
        return agents;
    }

    /** The bridges seen. */
    public Collection<KnownBridge> bridges() {
        return Collections.unmodifiableCollection(bridges.values());
    }

    /** The river as far as it has been seen. */
    public RiverMap river() {
        return river;
    }

    /** Where the castle may be. */
    public CastleEstimate castle() {
        return castle;
    }

    /** The compass sector of the castle at the latest perception; null before any. */
    public Sector castleSector() {
        return castleSector;
    }

    /** What the world looked like where the agent has looked. */
    public Coverage coverage() {
        return coverage;
    }

    /** Where the agent has stood. */
    public Trail trail() {
        return trail;
    }

    /** What rejected moves taught, oldest first. */
    public List<LearnedBlock> learned() {
        return Collections.unmodifiableList(learned);
    }

    /** The rules a person set that hold until lifted: where the agent must not go, what it must not take. */
    public Conduct conduct() {
        return conduct;
    }

    /** Grows whenever something that changes where the agent can walk changes, a rule about places included. */
    public long terrainVersion() {
        if ((castle.bounded() || castle.located()) && castle.version() != castleVersionSeen) {
            castleVersionSeen = castle.version();
            terrainVersion++; // the castle counts for walking only once it is near or located
        }
        return terrainVersion + river.version() + conduct.version();
    }

    /** Grows whenever a fruit is first seen or known to be gone. */
    public long fruitVersion() {
        return fruitVersion;
    }

    // ---- remembering ------------------------------------------------------------------------

    private void remember(PerceivedObject object, Point2 self, double facing) {
        Point2 at = Bearings.toWorld(self, facing, object.at());
        KnownObstacle known = obstacles.get(object.id());
        double accuracy = object.at().distance();
        if (known == null) {
            KnownObstacle fresh = new KnownObstacle(object.id(), object.kind(), at, object.radius(), object.height(),
                    accuracy, 0);
            obstacles.put(object.id(), fresh);
            castle.exclude(at, CastleEstimate.CORE_RADIUS + fresh.blockRadius() + 1.5);
            terrainVersion++;
        } else if (accuracy < known.accuracy() - 0.5) {
            boolean moved = known.centre().distance(at) > 0.02;
            obstacles.put(object.id(), known.placedAt(at, accuracy));
            if (moved) {
                terrainVersion++;
            }
        }
    }

    private void remember(PerceivedFruit seen) {
        if (gone.contains(seen.id())) {
            return;
        }
        KnownFruit before = fruit.put(seen.id(), new KnownFruit(seen.id(), seen.kind(), seen.position(),
                seen.radius(), seen.support(), tick));
        if (before == null) {
            fruitVersion++;
            castle.exclude(seen.position().onGround(), CastleEstimate.CORE_RADIUS);
        }
    }

    private void remember(PerceivedBridge seen, Point2 self, double facing) {
        double accuracy = Math.max(seen.entryA().distance(), seen.entryB().distance());
        Double known = bridgeAccuracy.get(seen.id());
        if (known != null && accuracy >= known - 0.5) {
            return;
        }
        KnownBridge bridge = new KnownBridge(seen.id(), Bearings.toWorld(self, facing, seen.entryA()),
                Bearings.toWorld(self, facing, seen.entryB()), seen.width());
        bridges.put(seen.id(), bridge);
        bridgeAccuracy.put(seen.id(), accuracy);
        river.bridged(bridge);
        terrainVersion++;
    }

    private void excludeCastle(Point2 self) {
        if (lastExcluded == null || lastExcluded.distance(self) > 2) {
            castle.exclude(self, CastleEstimate.CORE_RADIUS + radius);
            lastExcluded = self;
        }
        if (river.version() != riverVersionExcluded) {
            riverVersionExcluded = river.version();
            List<ShoreSighting> all = river.sightings();
            if (!all.isEmpty()) {
                ShoreSighting latest = all.get(all.size() - 1);
                castle.exclude(latest.shore(), CastleEstimate.CORE_RADIUS + CastleEstimate.WATER_CLEARANCE);
            }
        }
    }
}
