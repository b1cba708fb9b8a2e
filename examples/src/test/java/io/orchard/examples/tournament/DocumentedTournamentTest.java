package io.orchard.examples.tournament;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.examples.match.Lineup;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfSystemProperty;
import org.junit.jupiter.api.io.TempDir;

/**
 * The tables of docs/agents.md's tournament are the results.md of the tournament command shown
 * there, made by the same code: every build plays the first {@value #CHECKED} games of that
 * command again and finds their rows in the docs; {@code -Dorchard.tables=all} plays all its games
 * and finds both whole tables (a few minutes on two cores:
 * {@code ./mvnw -B -pl examples -am test -Dtest=DocumentedTournamentTest -Dsurefire.failIfNoSpecifiedTests=false
 * -Dorchard.tables=all}). When the agents or the server change the games, this test fails until the
 * tables are made again with that command.
 */
class DocumentedTournamentTest {

    private static final Path DOC = Path.of("..", "docs", "agents.md");
    private static final Pattern COMMAND = Pattern.compile(
            "\\./orchard tournament --games (\\d+) --agents (\\S+) --seed-from (\\d+) --time-limit (\\d+)");
    /** The games every build plays again. */
    static final int CHECKED = 2;

    @TempDir
    Path dir;

    /** The documented command's tournament, cut to {@code games} games. */
    private List<Played> play(Matcher command, int games) throws Exception {
        Tournament tournament = new Tournament(games, Lineup.parse(command.group(2), Map.of()),
                Long.parseLong(command.group(3)), Double.parseDouble(command.group(4)), Duration.ofSeconds(10), dir);
        return tournament.play(new ProgressBar(new PrintStream(OutputStream.nullOutputStream()), false, games));
    }

    private static String doc() throws IOException {
        return Files.readString(DOC, StandardCharsets.UTF_8);
    }

    private static Matcher command(String doc) {
        Matcher command = COMMAND.matcher(doc);
        assertThat(command.find()).as("docs/agents.md shows the tournament command").isTrue();
        return command;
    }

    @Test
    void theFirstGamesOfTheDocumentedTournamentPlayAsItsTableSays() throws Exception {
        String doc = doc();
        Matcher command = command(doc);
        List<String> names = Lineup.parse(command.group(2), Map.of()).names();
        int header = doc.indexOf(ResultTables.gameHeader(names));
        assertThat(header).as("the games' table, as results.md heads it").isNotNegative();

        List<Played> played = play(command, CHECKED);

        String table = doc.substring(header);
        for (Played game : played) {
            assertThat(game.missed()).as("turns missed in game %d", game.game()).isEmpty();
            assertThat(table).as("the row of seed %d", game.seed()).contains("\n" + ResultTables.gameRow(game) + "\n");
        }
    }

    @Test
    @EnabledIfSystemProperty(named = "orchard.tables", matches = "all")
    void theWholeDocumentedTournamentPlaysAsItsTablesSay() throws Exception {
        String doc = doc();
        Matcher command = command(doc);
        Lineup lineup = Lineup.parse(command.group(2), Map.of());

        List<Played> played = play(command, Integer.parseInt(command.group(1)));

        List<Result> rows = played.stream().flatMap(game -> game.rows().stream()).toList();
        String tables = ResultTables.markdown(played, lineup.names(),
                lineup.names().stream().map(agent -> Summary.of(agent, rows)).toList());
        assertThat(doc).contains(tables);
    }
}
