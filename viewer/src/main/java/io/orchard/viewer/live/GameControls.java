package io.orchard.viewer.live;

import io.orchard.protocol.message.ActionResultMessage;
import io.orchard.protocol.message.ErrorMessage;
import io.orchard.protocol.message.GameControlMessage;
import io.orchard.protocol.message.Reply;
import io.orchard.protocol.value.GameCommand;
import io.orchard.protocol.value.Outcome;
import java.util.function.Consumer;

/**
 * The viewer's keys that start, pause and continue a live game, and what the person at the keys is
 * told. Only the operator controls the game: a viewer started without the server's operator token
 * sends nothing and says how to become the operator; the operator's {@code GameControl} is sent and
 * its answer told, a refusal with the server's reason.
 *
 * <p>The server tells viewers no pause, so the controls keep what they believe: the game runs
 * while ticks come, and a pause or resume refused as not applying ("the game is not running", "the
 * game is not paused") shows the game is the other way, so the next key press does the other.
 */
public final class GameControls {

    /** Where the controls tell the person what happened; called on any thread. */
    public interface Notes {

        /** Something was done. */
        void event(String text);

        /** Something could not be done, and why. */
        void problem(String text);
    }

    /** What a viewer without the operator token is told when it asks to control the game. */
    public static final String NOT_OPERATOR = "is the operator's: start the viewer with --operator-token SECRET "
            + "(or ORCHARD_OPERATOR_TOKEN), the token the server was given with its --operator-token";

    private final ServerLink link;
    private final boolean operator;
    private final Notes notes;
    private volatile boolean paused;

    /**
     * Controls over {@code link}.
     *
     * @param operator whether the link presented an operator token
     */
    public GameControls(ServerLink link, boolean operator, Notes notes) {
        this.link = link;
        this.operator = operator;
        this.notes = notes;
    }

    /** Pauses the game, or continues it when it seems paused. */
    public void togglePause() {
        send(paused ? GameCommand.RESUME : GameCommand.PAUSE);
    }

    /** Starts the game without waiting for more agents. */
    public void start() {
        send(GameCommand.START);
    }

    /** A tick began: the game runs. */
    public void ticked() {
        paused = false;
    }

    private void send(GameCommand command) {
        String what = switch (command) {
            case START -> "starting the game";
            case PAUSE -> "pausing the game";
            case RESUME -> "continuing the game";
            case RESTART -> "restarting the game";
        };
        if (!operator) {
            notes.problem(capitalised(what) + " " + NOT_OPERATOR);
            return;
        }
        if (!link.isConnected()) {
            notes.problem("not connected to the server at " + link.server() + ": " + what + " was not asked for");
            return;
        }
        link.request(seq -> new GameControlMessage(seq, command)).whenComplete((reply, failure) -> {
            if (failure != null) {
                notes.problem(what + " failed: " + failure.getMessage());
            } else {
                answered(command, what, reply);
            }
        });
    }

    private void answered(GameCommand command, String what, Reply reply) {
        if (reply instanceof ActionResultMessage && command != GameCommand.START) {
            // Done, or refused as not applying ("the game is not running"): either way the game is now
            // as the command leaves it.
            paused = command == GameCommand.PAUSE;
        }
        if (reply instanceof ActionResultMessage result && result.outcome() == Outcome.ACCEPTED) {
            notes.event(switch (command) {
                case START -> "you started the game";
                case PAUSE -> "you paused the game";
                case RESUME -> "you continued the game";
                case RESTART -> "you restarted the game";
            });
        } else if (reply instanceof ActionResultMessage result) {
            notes.problem(what + " refused: " + result.reason());
        } else if (reply instanceof ErrorMessage error) {
            notes.problem(what + " refused by the server: " + error.code().wireName() + ": " + error.text());
        }
    }

    private static String capitalised(String text) {
        return Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }
}
