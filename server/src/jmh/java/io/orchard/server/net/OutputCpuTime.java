package io.orchard.server.net;

import io.orchard.server.bench.CpuRounds;

/**
 * {@link TickOutputBenchmark} timed on the thread's CPU clock ({@link CpuRounds}), for a machine
 * too busy for JMH's wall clock: a tick's output to 1,000 agents' clients in the ordinary and the
 * lean form, and the tick's broadcasts to viewers.
 *
 * <pre>
 * java -cp ... io.orchard.server.net.OutputCpuTime [agents 1000] [warm-up 300] [rounds 10] [per round 50]
 * </pre>
 */
public final class OutputCpuTime {

    private OutputCpuTime() {}

    /** Runs the rounds of each and prints them. */
    public static void main(String[] args) {
        int agents = args.length > 0 ? Integer.parseInt(args[0]) : 1000;
        int warmUp = args.length > 1 ? Integer.parseInt(args[1]) : 300;
        int rounds = args.length > 2 ? Integer.parseInt(args[2]) : 10;
        int perRound = args.length > 3 ? Integer.parseInt(args[3]) : 50;
        for (String form : new String[] {"ordinary", "lean"}) {
            TickOutputBenchmark bench = new TickOutputBenchmark();
            bench.agents = agents;
            bench.form = form;
            bench.setUp();
            CpuRounds.run(agents + " agents' output, " + form, bench::agents, warmUp, rounds, perRound);
            if (form.equals("lean")) {
                CpuRounds.run("the tick's broadcasts to viewers", bench::viewerBroadcasts, warmUp, rounds, perRound);
            }
        }
    }
}
