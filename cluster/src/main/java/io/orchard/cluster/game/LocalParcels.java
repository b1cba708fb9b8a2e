package io.orchard.cluster.game;

import io.orchard.cluster.order.KeyedLine;
import io.orchard.cluster.order.LineKey;
import io.orchard.cluster.parcel.OwnedAgent;
import io.orchard.cluster.parcel.Parcel;
import io.orchard.cluster.parcel.ParcelGrid;
import io.orchard.cluster.parcel.ParcelId;
import io.orchard.cluster.parcel.PathQuery;
import io.orchard.server.sim.AgentHandover;
import io.orchard.server.sim.FirstContact;
import io.orchard.server.sim.SimulationConfig;
import io.orchard.server.world.World;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/** Every parcel of a split game as an object of this JVM, called one after the other. */
public final class LocalParcels implements Parcels {

    private final Map<ParcelId, Parcel> parcels = new TreeMap<>();
    private final ParcelGrid grid;
    private final World world;
    private final SimulationConfig config;

    /** A parcel for every square of {@code grid}, each with its own fruit of {@code world}. */
    public LocalParcels(ParcelGrid grid, World world, SimulationConfig config) {
        this.grid = grid;
        this.world = world;
        this.config = config;
        for (ParcelId id : grid.all()) {
            parcels.put(id, new Parcel(id, grid, world.withOwnFruit(), config));
        }
    }

    @Override
    public void reset(Set<String> fruitLeft) {
        for (ParcelId id : grid.all()) {
            Parcel parcel = new Parcel(id, grid, world.withOwnFruit(), config);
            parcel.keepOnly(fruitLeft);
            parcels.put(id, parcel);
        }
    }

    @Override
    public void own(Map<ParcelId, List<OwnedAgent>> agents) {
        agents.forEach((id, own) -> parcels.get(id).own(own));
    }

    @Override
    public List<AgentHandover> release(Map<ParcelId, List<String>> names) {
        List<AgentHandover> released = new ArrayList<>();
        names.forEach((id, gone) -> released.addAll(parcels.get(id).release(gone)));
        return released;
    }

    @Override
    public void addGhosts(Map<ParcelId, List<OwnedAgent>> ghosts) {
        ghosts.forEach((id, added) -> parcels.get(id).addGhosts(added));
    }

    @Override
    public void forgetGhosts(Map<ParcelId, List<String>> names) {
        names.forEach((id, gone) -> parcels.get(id).forgetGhosts(gone));
    }

    @Override
    public List<KeyedLine> perceive(long tick, double time, Map<ParcelId, List<OwnedAgent>> ghosts) {
        List<KeyedLine> lines = new ArrayList<>();
        ghosts.forEach((id, held) -> {
            Parcel parcel = parcels.get(id);
            parcel.ghosts(held);
            lines.addAll(parcel.perceive(tick, time));
        });
        return lines;
    }

    @Override
    public Map<PathQuery, FirstContact> firstAlong(Map<ParcelId, List<PathQuery>> paths) {
        Map<PathQuery, FirstContact> first = new HashMap<>();
        paths.forEach((id, asked) -> FirstContacts.add(first, asked, parcels.get(id).firstAlong(asked)));
        return first;
    }

    @Override
    public Applied apply(long tick, double time, Map<ParcelId, List<Parcel.Act>> acts,
                         Map<PathQuery, FirstContact> answers) {
        List<KeyedLine> lines = new ArrayList<>();
        List<Parcel.KeyedClaim> claims = new ArrayList<>();
        List<AgentHandover> owned = new ArrayList<>();
        List<String> removed = new ArrayList<>();
        acts.forEach((id, own) -> {
            Parcel parcel = parcels.get(id);
            lines.addAll(parcel.apply(tick, time, own, answers));
            claims.addAll(parcel.takeClaims());
            owned.addAll(parcel.owned());
            removed.addAll(parcel.takeRemoved());
        });
        return new Applied(lines, claims, owned, removed);
    }

    @Override
    public Grasped grasp(long tick, double time, Map<ParcelId, List<Parcel.ClaimOf>> claims,
                         Map<String, LineKey> firstClaims) {
        List<KeyedLine> lines = new ArrayList<>();
        List<Parcel.Taken> taken = new ArrayList<>();
        claims.forEach((id, own) -> lines.addAll(parcels.get(id).grasp(tick, time, own, firstClaims::get, taken)));
        return new Grasped(lines, taken);
    }

    @Override
    public void fruitTaken(Map<ParcelId, List<String>> fruit) {
        fruit.forEach((id, taken) -> parcels.get(id).fruitTaken(taken));
    }

    @Override
    public Walked walk(long tick, double time, Map<ParcelId, List<OwnedAgent>> ghosts) {
        List<KeyedLine> lines = new ArrayList<>();
        List<AgentHandover> left = new ArrayList<>();
        List<AgentHandover> owned = new ArrayList<>();
        ghosts.forEach((id, held) -> {
            Parcel parcel = parcels.get(id);
            parcel.ghosts(held);
            lines.addAll(parcel.walk(tick, time, left));
            owned.addAll(parcel.owned());
        });
        return new Walked(lines, left, owned);
    }

    @Override
    public void walked(Map<ParcelId, List<AgentHandover>> agents) {
        agents.forEach((id, walked) -> parcels.get(id).walked(walked));
    }
}
