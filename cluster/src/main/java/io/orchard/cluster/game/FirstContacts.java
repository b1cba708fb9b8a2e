package io.orchard.cluster.game;

import io.orchard.cluster.parcel.PathQuery;
import io.orchard.server.sim.FirstContact;
import java.util.List;
import java.util.Map;

/** Puts together the first contacts that several parcels answered for the same paths. */
public final class FirstContacts {

    private FirstContacts() {}

    /**
     * Adds one parcel's answers (null: none on that path) to {@code first}, keeping the first of all;
     * a path that meets no agent maps to null, so that every path asked is answered.
     */
    public static void add(Map<PathQuery, FirstContact> first, List<PathQuery> asked, List<FirstContact> answers) {
        for (int i = 0; i < asked.size(); i++) {
            FirstContact answer = answers.get(i);
            first.putIfAbsent(asked.get(i), null);
            if (answer != null && answer.before(first.get(asked.get(i)))) {
                first.put(asked.get(i), answer);
            }
        }
    }
}
