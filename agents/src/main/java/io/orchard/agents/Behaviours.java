package io.orchard.agents;

import io.orchard.agents.behaviour.Forager;
import io.orchard.agents.behaviour.Motor;
import io.orchard.agents.behaviour.PathPlanner;
import io.orchard.agents.errand.Errands;
import io.orchard.agents.language.Discourse;
import io.orchard.agents.language.Goal;
import io.orchard.agents.language.InstructionInterpreter;
import io.orchard.agents.language.Interpretation;
import io.orchard.agents.language.Language;
import java.util.List;
import java.util.function.Consumer;
import java.util.random.RandomGenerator;

/**
 * The agent's defaults, each made on first use once the agent is in the world: one path planner,
 * whose map of the ground is kept up to date once for everything that plans; the autonomy
 * ({@link Forager}); and the instructions, read by an {@link InstructionInterpreter} and pursued
 * by the {@link Errands}. The harvesters of the forager and the errands play the body's grasp
 * animation with each grasp.
 */
final class Behaviours {

    private static final double GRASP_SECONDS = 1.5;

    private final String agent;
    private final Situation situation;
    private final Motor motor;
    private final RandomGenerator random;
    private PathPlanner planner;
    private Forager forager;
    private Errands errands;
    private InstructionInterpreter interpreter;
    private volatile Language language = Language.ENGLISH;

    Behaviours(String agent, Situation situation, Motor motor, RandomGenerator random) {
        this.agent = agent;
        this.situation = situation;
        this.motor = motor;
        this.random = random;
    }

    /** The default interpreter of instructions, knowing the agent's name, in its language and English. */
    InstructionInterpreter interpreter() {
        InstructionInterpreter made = interpreter;
        if (made == null || made.languages().get(0) != language) {
            made = new InstructionInterpreter(List.of(agent), language);
            interpreter = made;
        }
        return made;
    }

    /** Has the agent understand this language besides English; safe from any thread. */
    void understand(Language own) {
        this.language = own;
    }

    PathPlanner planner() {
        if (planner == null) {
            planner = new PathPlanner(situation.memory());
        }
        return planner;
    }

    Forager forager() {
        if (forager == null) {
            forager = new Forager(situation.memory(), motor, planner(), random);
            String graspAnimation = situation.plan().graspAnimation();
            if (graspAnimation != null) {
                forager.harvester().gesture(fruit -> motor.play(graspAnimation, GRASP_SECONDS));
            }
        }
        return forager;
    }

    Errands errands() {
        if (errands == null) {
            errands = new Errands(situation.memory(), motor, planner());
            String graspAnimation = situation.plan().graspAnimation();
            if (graspAnimation != null) {
                errands.harvester().gesture(fruit -> motor.play(graspAnimation, GRASP_SECONDS));
            }
        }
        return errands;
    }

    /** One tick of the instructed goal, if there is one; the autonomy rests while it has the agent. */
    boolean pursueInstruction() {
        boolean held = situation.inWorld() && errands().step();
        if (held && forager != null) {
            forager.pause();
        }
        return held;
    }

    /**
     * What the agent does with an instruction it heard, as {@link AgentController#onInstruction}
     * describes it: a goal it understood goes to {@code onGoal}.
     */
    void heard(String text, Interpretation heard, Consumer<Goal> onGoal) {
        if (!heard.isFor(agent)) {
            motor.say(heard.language() == Language.GERMAN ? "Das war für " + heard.addressee().orElseThrow()
                    + ", nicht für mich." : "That was for " + heard.addressee().orElseThrow() + ", not for me.");
            return;
        }
        if (situation.inWorld()) {
            errands().speak(heard.language()); // the answers, and what it says as it goes, in the sentence's language
        }
        if (heard instanceof Interpretation.Understood understood) {
            if (!understood.restatement().equals(understood.goal().restatement(understood.language()))) {
                // Read by another interpreter than the grammar (a language model, a student's): what
                // it made of the sentence is said before the errand announces itself.
                motor.say(understood.restatement());
            }
            onGoal.accept(understood.goal());
        } else if (heard instanceof Interpretation.NotUnderstood notUnderstood) {
            if (!errands().answer(text)) {
                motor.say(errands().asking() ? notUnderstood.answer() + " " + errands().question()
                        : notUnderstood.answer());
            }
        }
    }

    /** What the agent spoke about or looked at last; nothing before it is in the world. */
    Discourse discourse() {
        return situation.inWorld() ? errands().discourse() : Discourse.NONE;
    }

    /** Whether an instructed goal has the agent. */
    boolean instructed() {
        return errands != null && errands.busy();
    }
}
