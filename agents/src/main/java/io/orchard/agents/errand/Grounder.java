package io.orchard.agents.errand;

import io.orchard.agents.language.Place;
import io.orchard.agents.language.Reference;
import io.orchard.agents.language.Reference.Kind;
import io.orchard.agents.map.Bearings;
import io.orchard.agents.map.CastleEstimate;
import io.orchard.agents.map.KnownBridge;
import io.orchard.agents.map.KnownFruit;
import io.orchard.agents.map.KnownObstacle;
import io.orchard.agents.map.RiverMap;
import io.orchard.agents.map.SeenAgent;
import io.orchard.agents.map.ShoreSighting;
import io.orchard.agents.map.WorldMemory;
import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.Sector;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.function.Predicate;

/**
 * Finds, in what the agent remembers now, the objects a {@link Reference} describes: of its kind
 * (and name), fitting its place ("on the table", "by the river", "north of the castle") and size,
 * then chosen by distance or size when the words say so. Grounding is done again as memory grows,
 * so a reference that fits nothing today may fit something tomorrow.
 */
final class Grounder {

    /** "Near" something: its edge within this many units. */
    static final double NEAR = 10;

    /** The castle's size as the agent reckons it: its core, and a little more. */
    static final double CASTLE_SIZE = CastleEstimate.CORE_RADIUS + 3;

    /** How far off a compass direction a thing may lie and still be "north of" something. */
    private static final double COMPASS_SLACK = Math.toRadians(60);

    /** How far off its side a thing may lie and still be "on your left" (or right, ahead, behind). */
    private static final double SIDE_SLACK = Math.toRadians(60);

    private final WorldMemory memory;
    private Point2 toldAt;
    private double toldHeading;

    Grounder(WorldMemory memory) {
        this.memory = memory;
    }

    /**
     * Where the agent stood, and which way it faced, when it was told: "on your left", "near you"
     * are taken from there, though it moves while it looks.
     */
    void told(Point2 where, double heading) {
        this.toldAt = where;
        this.toldHeading = heading;
    }

    /** Where the agent started the game: "where you started"; where it is, before it knows. */
    Point2 start() {
        Point2 start = memory.start();
        return start != null ? start : memory.position();
    }

    /** Grounds the reference: the one it means, several to choose between, or none yet. */
    Grounding ground(Reference reference) {
        List<Known> fits = fitting(reference);
        if (fits.isEmpty()) {
            return new Grounding.Unknown();
        }
        List<Known> chosen = select(reference, fits);
        if (chosen.isEmpty()) {
            return new Grounding.Unknown(); // "the fifth tree" when it knows of four
        }
        if (chosen.size() > 1 && asksWhich(reference.kind())) {
            return new Grounding.Ambiguous(chosen);
        }
        return new Grounding.Found(chosen);
    }

    /**
     * Every known object that fits the reference's kind, name, place and size, nearest first;
     * distance and the superlatives (largest, smallest) are not applied.
     */
    List<Known> fitting(Reference reference) {
        List<Known> all = known(reference);
        if (reference.place() != null) {
            Predicate<Known> at = where(reference.place());
            all.removeIf(at.negate());
        }
        if (reference.size() == Reference.Size.BIG || reference.size() == Reference.Size.SMALL) {
            double median = median(known(Reference.to(reference.kind())));
            boolean big = reference.size() == Reference.Size.BIG;
            all.removeIf(k -> big ? k.size() < median - 1e-9 : k.size() > median + 1e-9);
        }
        Point2 here = memory.position();
        all.sort(Comparator.comparingDouble(k -> k.where().distance(here)));
        Place place = reference.place();
        if (place != null && place.anchor() != null && !all.isEmpty()
                && (place.relation() == Place.Relation.CLOSEST_TO || place.relation() == Place.Relation.FARTHEST_FROM)) {
            List<Known> anchors = select(place.anchor(), fitting(place.anchor()));
            if (anchors.isEmpty()) {
                return new ArrayList<>();
            }
            Comparator<Known> byAnchor = Comparator.comparingDouble(k -> anchors.stream()
                    .mapToDouble(a -> a.where().distance(k.where()) - a.size()).min().orElseThrow());
            Known picked = place.relation() == Place.Relation.CLOSEST_TO ? all.stream().min(byAnchor).orElseThrow()
                    : all.stream().max(byAnchor).orElseThrow();
            return new ArrayList<>(List.of(picked));
        }
        return all;
    }

    /**
     * The objects of {@code fits} the reference's distance or superlative picks out (one, or none
     * when its ordinal counts past those that fit), or all of them when it names neither; nearest
     * first.
     */
    List<Known> select(Reference reference, List<Known> fits) {
        if (fits.isEmpty()) {
            return fits;
        }
        if (reference.distance() != null) {
            List<Known> ordered = ordered(reference.distance(), fits);
            int index = reference.ordinal() == null ? 0 : reference.ordinal() - 1;
            return index < ordered.size() ? List.of(ordered.get(index)) : List.of();
        }
        if (reference.size() == Reference.Size.LARGEST) {
            return List.of(fits.stream().max(Comparator.comparingDouble(Known::size)).orElseThrow());
        }
        if (reference.size() == Reference.Size.SMALLEST) {
            return List.of(fits.stream().min(Comparator.comparingDouble(Known::size)).orElseThrow());
        }
        return fits;
    }

    /**
     * The objects that fit, in the order of a distance or superlative, the one it picks first: nearest
     * first for "nearest", farthest first for "farthest", highest first for "highest", and so on. From
     * the left and the right counts only what lies ahead of the agent, as it faced when told, when
     * anything fitting lies there.
     */
    private List<Known> ordered(Reference.Distance distance, List<Known> fits) {
        List<Known> ordered = new ArrayList<>(fits);
        Comparator<Known> by = switch (distance) {
            case NEAREST, FARTHEST -> Comparator.comparingDouble(k -> k.where().distance(memory.position()));
            case HIGHEST, LOWEST -> Comparator.comparingDouble(k -> k.fruit() == null ? 0 : k.fruit().height());
            case NORTHERNMOST, SOUTHERNMOST -> Comparator.comparingDouble(k -> k.where().z());
            case EASTERNMOST, WESTERNMOST -> Comparator.comparingDouble(k -> k.where().x());
            case LEFTMOST, RIGHTMOST -> Comparator.comparingDouble(this::bearingFromTold);
        };
        if (distance == Reference.Distance.LEFTMOST || distance == Reference.Distance.RIGHTMOST) {
            List<Known> ahead = ordered.stream().filter(k -> Math.abs(bearingFromTold(k)) <= Math.PI / 2).toList();
            if (!ahead.isEmpty()) {
                ordered = new ArrayList<>(ahead);
            }
        }
        boolean greatestFirst = switch (distance) {
            case FARTHEST, HIGHEST, SOUTHERNMOST, EASTERNMOST, LEFTMOST -> true; // north is -z, west is -x, left +
            default -> false;
        };
        ordered.sort(greatestFirst ? by.reversed() : by);
        return ordered;
    }

    /** The bearing of a thing from where the agent stood, as it faced, when told: positive to its left. */
    private double bearingFromTold(Known k) {
        double facing = toldAt == null ? memory.heading() : toldHeading;
        return Bearings.bearing(toldAt(), facing, k.where());
    }

    /**
     * Whether a thing stands in this place: "on the table", "near the castle"... False when the
     * place's anchor is not known yet.
     */
    Predicate<Known> where(Place place) {
        Place.Relation relation = place.relation();
        Reference anchorReference = place.anchor();
        if (relation == Place.Relation.ON_GROUND) {
            return k -> k.fruit() == null || k.fruit().onGround();
        }
        if (anchorReference == null) {
            Point2 here = toldAt();
            if (relation == Place.Relation.NEAR) {
                return k -> k.where().distance(here) <= k.size() + NEAR; // "near you"
            }
            if (relation.fromHeading()) {
                double facing = toldAt == null ? memory.heading() : toldHeading;
                double side = sideHeading(relation) - facing;
                return k -> k.where().distance(here) > 1e-6 && Math.abs(Bearings.normalise(
                        Bearings.bearing(here, facing, k.where()) - side)) <= SIDE_SLACK;
            }
            return k -> inSector(here, k.where(), relation.sector());
        }
        if (relation == Place.Relation.CLOSEST_TO || relation == Place.Relation.FARTHEST_FROM) {
            return k -> true; // the one is picked among those that fit, in fitting()
        }
        List<Known> anchors = anchorReference.kind() == Kind.PLACE ? List.of()
                : select(anchorReference, fitting(anchorReference));
        Kind anchorKind = anchorReference.kind();
        boolean riverSide = anchorKind == Kind.RIVER || anchorKind == Kind.BRIDGE;
        if (riverSide && (relation == Place.Relation.BEYOND || relation == Place.Relation.THIS_SIDE_OF)) {
            return sideOfRiver(relation == Place.Relation.BEYOND);
        }
        if (anchorKind == Kind.RIVER && relation == Place.Relation.NEAR) {
            RiverMap river = memory.river();
            return k -> river.side(k.where().x(), k.where().z(), NEAR) == RiverMap.Side.WATER;
        }
        if (anchorKind == Kind.FOREST) {
            List<Known> trees = known(Reference.to(Kind.TREE));
            double reach = relation == Place.Relation.NEAR ? NEAR : 3;
            return k -> (k.fruit() != null && k.fruit().support() != null
                    && memory.obstacle(k.fruit().support()).map(KnownObstacle::isTree).orElse(false))
                    || trees.stream().anyMatch(t -> t.where().distance(k.where()) <= t.size() + reach);
        }
        if (anchors.isEmpty()) {
            return k -> false;
        }
        Set<String> ids = new HashSet<>();
        anchors.forEach(a -> ids.add(a.id()));
        Point2 here = memory.position();
        return switch (relation) {
            case ON, IN -> k -> k.fruit() != null
                    ? k.fruit().support() != null && ids.contains(k.fruit().support())
                    : anchors.stream().anyMatch(a -> !a.id().equals(k.id())
                            && a.where().distance(k.where()) <= a.size());
            case UNDER -> k -> (k.fruit() == null || k.fruit().onGround())
                    && anchors.stream().anyMatch(a -> !a.id().equals(k.id())
                            && a.where().distance(k.where()) <= a.size() + 0.5);
            case NEAR -> k -> anchors.stream().anyMatch(a -> !a.id().equals(k.id())
                    && a.where().distance(k.where()) <= a.size() + NEAR);
            case BEYOND -> k -> anchors.stream().anyMatch(a -> behind(here, a.where(), k.where()));
            case THIS_SIDE_OF -> k -> anchors.stream().noneMatch(a -> behind(here, a.where(), k.where()));
            default -> k -> anchors.stream().anyMatch(a -> !a.id().equals(k.id())
                    && inSector(a.where(), k.where(), relation.sector()));
        };
    }

    /** The side of the river, as the agent knows it, that a point lies on. */
    RiverMap.Side side(Point2 p) {
        return memory.river().side(p.x(), p.z(), 0);
    }

    /** Every known object of the reference's kind (and name), nearest first. */
    List<Known> known(Reference reference) {
        List<Known> found = new ArrayList<>();
        Kind kind = reference.kind();
        Point2 here = memory.position();
        if (kind.isFruit()) {
            for (KnownFruit fruit : memory.fruit()) {
                if (kind.matches(fruit.kind())) {
                    found.add(new Known(fruitKind(fruit), fruit.id(), fruit.ground(), fruit.radius(), fruit, null));
                }
            }
        } else if (kind.objectKind() != null) {
            for (KnownObstacle obstacle : memory.obstacles()) {
                if (obstacle.kind() == kind.objectKind()) {
                    found.add(Known.of(kind, obstacle.id(), obstacle.centre(), obstacle.radius()));
                }
            }
        } else if (kind == Kind.BRIDGE) {
            for (KnownBridge bridge : memory.bridges()) {
                found.add(new Known(kind, bridge.id(), bridge.middle(), bridge.length() / 2, null, bridge));
            }
        } else if (kind == Kind.CASTLE) {
            if (memory.castleSector() != null) {
                memory.castle().centre().ifPresent(c -> found.add(Known.of(kind, "castle", c, CASTLE_SIZE)));
            }
        } else if (kind == Kind.RIVER) {
            memory.river().sightings().stream()
                    .min(Comparator.comparingDouble((ShoreSighting s) -> s.shore().distance(here)))
                    .ifPresent(s -> found.add(Known.of(kind, "river", s.shore(), 0)));
        } else if (kind == Kind.FOREST) {
            memory.obstacles().stream().filter(KnownObstacle::isTree)
                    .min(Comparator.comparingDouble(t -> t.centre().distance(here)))
                    .ifPresent(t -> found.add(Known.of(kind, "forest", t.centre(), t.radius())));
        } else if (kind == Kind.START) {
            found.add(Known.of(kind, "start", start(), 0));
        } else if (kind == Kind.AGENT) {
            for (SeenAgent agent : memory.agents()) {
                if (reference.name() == null || agent.name().equalsIgnoreCase(reference.name())) {
                    found.add(Known.of(kind, agent.name(), agent.position(), agent.radius()));
                }
            }
        }
        if (reference.id() != null) {
            found.removeIf(k -> !k.id().equals(reference.id())); // "that table": the one spoken of
        }
        return found;
    }

    /**
     * The heading of a side of the agent, as it faced when told: its heading for "ahead", a
     * quarter turn more for "on your left" (headings grow to the left).
     */
    double sideHeading(Place.Relation relation) {
        double facing = toldAt == null ? memory.heading() : toldHeading;
        return switch (relation) {
            case LEFT -> facing + Math.PI / 2;
            case RIGHT -> facing - Math.PI / 2;
            case BEHIND -> facing + Math.PI;
            default -> facing;
        };
    }

    /** Where the agent stood when told; where it stands, before it is told anything. */
    Point2 toldAt() {
        return toldAt == null ? memory.position() : toldAt;
    }

    /** Whether the person must be asked which one is meant when several fit: for landmarks, not for fruit or agents. */
    static boolean asksWhich(Kind kind) {
        return kind == Kind.TREE || kind == Kind.TABLE || kind == Kind.BRIDGE;
    }

    private Predicate<Known> sideOfRiver(boolean beyond) {
        RiverMap.Side mine = side(memory.position());
        if (mine != RiverMap.Side.LOW && mine != RiverMap.Side.HIGH) {
            return k -> false; // the river is not known, or the agent stands on a bridge
        }
        return k -> {
            RiverMap.Side theirs = side(k.where());
            return (theirs == RiverMap.Side.LOW || theirs == RiverMap.Side.HIGH) && (theirs != mine) == beyond;
        };
    }

    private static boolean behind(Point2 here, Point2 anchor, Point2 thing) {
        double ax = anchor.x() - here.x();
        double az = anchor.z() - here.z();
        double dot = ax * (thing.x() - anchor.x()) + az * (thing.z() - anchor.z());
        return dot > 0 && thing.distance(here) > anchor.distance(here);
    }

    /** Whether {@code thing} lies in the compass direction of {@code sector} from {@code from}. */
    static boolean inSector(Point2 from, Point2 thing, Sector sector) {
        if (from.distance(thing) < 1e-6) {
            return false;
        }
        double wanted = Math.toRadians(45.0 * sector.ordinal());
        double actual = Math.atan2(thing.x() - from.x(), -(thing.z() - from.z()));
        double off = Math.abs(Math.IEEEremainder(actual - wanted, 2 * Math.PI));
        return off <= COMPASS_SLACK;
    }

    /** The compass sector of {@code thing} seen from {@code from}, in words: "north-east". */
    static String compass(Point2 from, Point2 thing) {
        return Sector.of(thing.x() - from.x(), thing.z() - from.z()).wireName();
    }

    private static double median(List<Known> all) {
        if (all.isEmpty()) {
            return 0;
        }
        double[] sizes = all.stream().mapToDouble(Known::size).sorted().toArray();
        int n = sizes.length;
        return n % 2 == 1 ? sizes[n / 2] : (sizes[n / 2 - 1] + sizes[n / 2]) / 2;
    }

    private static Kind fruitKind(KnownFruit fruit) {
        return Kind.valueOf(fruit.kind().name());
    }

    /** Where a thing is in words, seen from {@code from}: "12 m to the north-east". */
    static String bearingWords(Point2 from, Point2 thing) {
        return String.format(Locale.ROOT, "%.0f m to the %s", from.distance(thing), compass(from, thing));
    }

    /** The castle's estimated centre, once its sector has been perceived; empty before. */
    Optional<Point2> castle() {
        return memory.castleSector() == null ? Optional.empty() : memory.castle().centre();
    }
}
