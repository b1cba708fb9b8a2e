package io.orchard.web;

import io.orchard.agents.AgentController;
import io.orchard.agents.zoo.Bunny;
import io.orchard.agents.zoo.Dwarf;
import io.orchard.agents.zoo.Guppy;
import io.orchard.agents.zoo.Roadrunner;
import io.orchard.agents.zoo.Robot;
import io.orchard.server.WorldServer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;

/**
 * The pictures of docs/web.md, taken by the page itself in Debian's headless Chromium: a live game
 * of seed 1998 with the paper's five agents, the overview after {@code SECONDS} of game time, then
 * following an agent. Run with the web module's test class path: {@code PageScreenshots OUT_DIR
 * [SECONDS [AGENT]]}; it writes {@code web.png} and {@code web-follow.png} into OUT_DIR.
 */
final class PageScreenshots {

    private PageScreenshots() {}

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args.length > 0 ? args[0] : "target");
        double seconds = args.length > 1 ? Double.parseDouble(args[1]) : 12;
        String followed = args.length > 2 ? args[2] : "Robot";
        Files.createDirectories(out);
        List<AgentController> agents = List.of(new Dwarf(), new Robot(), new Guppy(), new Bunny(), new Roadrunner());
        ExecutorService threads = Executors.newFixedThreadPool(agents.size());
        try (WorldServer server = WorldServer.builder().port(0).httpPort(0).seed(1998).start();
                Chromium browser = Chromium.start(1280, 720)) {
            agents.forEach(agent -> threads.submit(() -> agent.run("127.0.0.1", server.port())));
            browser.open("http://127.0.0.1:" + server.httpPort().orElseThrow() + "/");
            browser.await("window.orchard && orchard.ready && orchard.agents().length === " + agents.size()
                    + " && orchard.agents().every(a => orchard.model(a))", Duration.ofSeconds(120));
            browser.await("orchard.time >= " + seconds, Duration.ofSeconds(120 + (long) seconds * 4));
            server.pauseGame();
            Thread.sleep(1_000);
            ImageIO.write(browser.screenshot(), "png", out.resolve("web.png").toFile());
            browser.evaluate("orchard.follow('" + followed + "')");
            Thread.sleep(1_000);
            ImageIO.write(browser.screenshot(), "png", out.resolve("web-follow.png").toFile());
            System.out.println("wrote " + out.resolve("web.png") + " and " + out.resolve("web-follow.png") + " at t = "
                    + browser.evaluate("orchard.time").asDouble() + " s");
            browser.console().forEach(line -> System.out.println("page " + line));
        } finally {
            agents.forEach(AgentController::stop);
            threads.shutdown();
            threads.awaitTermination(10, TimeUnit.SECONDS);
        }
    }
}
