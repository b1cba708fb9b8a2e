package io.orchard.cluster.node;

import com.typesafe.config.Config;
import com.typesafe.config.ConfigFactory;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The Pekko settings of an Orchard node: a cluster member reached at {@code host:port} (port 0: any
 * free one), joining through the seed nodes given, its parcels never passivated (a parcel's state is
 * the game's), messages of up to 2 MiB between nodes, and the node left to the program on shutdown
 * rather than ending the JVM.
 */
public final class NodeSettings {

    /** The name of every Orchard node's actor system: nodes of one cluster share it. */
    public static final String SYSTEM = "orchard";

    private NodeSettings() {}

    /**
     * The settings of a node at {@code host:port} joining the cluster through {@code seeds}
     * ({@code host:port} each; none: the node joins itself, or is told whom to join).
     */
    public static Config of(String host, int port, List<String> seeds) {
        return of(host, port, seeds, java.time.Duration.ofSeconds(20));
    }

    /**
     * The settings of a node at {@code host:port} joining the cluster through {@code seeds}, which
     * takes a member that stopped answering for {@code downAfter} for lost (Pekko's split brain
     * resolver, keeping the side with the most members).
     */
    public static Config of(String host, int port, List<String> seeds, java.time.Duration downAfter) {
        String seedNodes = seeds.stream().map(seed -> "\"pekko://" + SYSTEM + "@" + seed + "\"")
                .collect(Collectors.joining(", ", "[", "]"));
        return ConfigFactory.parseString(String.format(Locale.ROOT, """
                pekko {
                  loglevel = "WARNING"
                  loggers = ["org.apache.pekko.event.slf4j.Slf4jLogger"]
                  logging-filter = "org.apache.pekko.event.slf4j.Slf4jLoggingFilter"
                  actor.provider = "cluster"
                  remote.artery.canonical.hostname = "%s"
                  remote.artery.canonical.port = %d
                  # A tick's lines of a crowded parcel may pass the default 256 KiB.
                  remote.artery.advanced.maximum-frame-size = 2 MiB
                  remote.artery.advanced.buffer-pool-size = 32
                  # A busy machine may take more than the default 3 s to bind the node's port.
                  remote.artery.bind.bind-timeout = 30s
                  cluster {
                    seed-nodes = %s
                    downing-provider-class = "org.apache.pekko.cluster.sbr.SplitBrainResolverProvider"
                    split-brain-resolver.stable-after = %d ms
                    jmx.enabled = off
                    sharding.passivation.strategy = "none"
                  }
                  coordinated-shutdown.exit-jvm = off
                  coordinated-shutdown.run-by-jvm-shutdown-hook = off
                }
                """, host, port, seedNodes, downAfter.toMillis())).withFallback(ConfigFactory.load());
    }
}
