package io.orchard.agents;

import io.orchard.protocol.value.Body;
import io.orchard.protocol.value.Checks;
import io.orchard.protocol.value.Gripper;
import io.orchard.protocol.value.Nullable;
import io.orchard.protocol.value.Sight;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Objects;
import java.util.Set;

/**
 * Everything an agent registers: its physical body (radius, height, speed, gripper, sight), its
 * visual model (a resource next to the agent's class: X3D, VRML97 or glTF), the joints and time
 * sensors of the model it will drive, which of those animate walking and grasping, and how often
 * it wants to perceive. Immutable; built with {@link #builder()}, whose every setter checks its
 * value at once.
 *
 * <pre>{@code
 * AgentBody.builder()
 *         .radius(0.4).height(1.2).speed(6)
 *         .gripper("hands", 0.6, 0, 1.6)
 *         .sight(40, Math.toRadians(200))
 *         .model("models/Dwarf.x3d")
 *         .joints("LeftShoulder", "RightShoulder")
 *         .walkAnimation("DwarfTSWalk").graspAnimation("DwarfTSGrasp")
 *         .build();
 * }</pre>
 *
 * <p>Every value has a default, so {@code AgentBody.builder().build()} is a working body: radius
 * 0.5, height 1.5, speed 5, hands reaching 0.6 from the ground up to 1.5, sight 40 units over
 * 200 degrees, no model (viewers show a placeholder), a perception every tick.
 */
public final class AgentBody {

    private final Body body;
    private final String model;
    private final String modelName;
    private final List<String> joints;
    private final List<String> timeSensors;
    private final String walkAnimation;
    private final String graspAnimation;
    private final int perceptionEvery;

    private AgentBody(Builder builder) {
        this.body = new Body(builder.radius, builder.height, builder.speed,
                new Gripper(builder.part, builder.reach, builder.minHeight, builder.maxHeight),
                new Sight(builder.range, builder.fieldOfView));
        this.model = builder.model;
        this.modelName = builder.modelName;
        this.joints = List.copyOf(builder.joints);
        this.timeSensors = List.copyOf(builder.timeSensors);
        this.walkAnimation = builder.walkAnimation;
        this.graspAnimation = builder.graspAnimation;
        this.perceptionEvery = builder.perceptionEvery;
    }

    /** A builder with the defaults. */
    public static Builder builder() {
        return new Builder();
    }

    /** The body asked for (the server may clamp it: the controller uses the body in force). */
    public Body body() {
        return body;
    }

    /** The model's resource, relative to the agent's class (or absolute with a leading '/'); null for none. */
    public @Nullable String model() {
        return model;
    }

    /** The name the model gives its root Transform, when it differs from the agent's; null when the same. */
    public @Nullable String modelName() {
        return modelName;
    }

    /** The joints to register, in order. */
    public List<String> joints() {
        return joints;
    }

    /** The time sensors to register, in order (the walk and grasp animations among them). */
    public List<String> timeSensors() {
        return timeSensors;
    }

    /** The time sensor that animates walking; null for none. */
    public @Nullable String walkAnimation() {
        return walkAnimation;
    }

    /** The time sensor that animates grasping; null for none. */
    public @Nullable String graspAnimation() {
        return graspAnimation;
    }

    /** Perceive every this many ticks. */
    public int perceptionEvery() {
        return perceptionEvery;
    }

    /** Builds an {@link AgentBody}; each setter checks its value and names it when it is wrong. */
    public static final class Builder {

        private double radius = 0.5;
        private double height = 1.5;
        private double speed = 5;
        private String part = "hands";
        private double reach = 0.6;
        private double minHeight = 0;
        private double maxHeight = 1.5;
        private double range = 40;
        private double fieldOfView = Math.toRadians(200);
        private String model;
        private String modelName;
        private final Set<String> joints = new LinkedHashSet<>();
        private final Set<String> timeSensors = new LinkedHashSet<>();
        private String walkAnimation;
        private String graspAnimation;
        private int perceptionEvery = 1;

        private Builder() {}

        /** The radius of the body's cylinder, in units (the server allows 0.2 to 2). */
        public Builder radius(double value) {
            this.radius = Checks.positive(value, "radius");
            return this;
        }

        /** The body's height (the server allows at most 4). */
        public Builder height(double value) {
            this.height = Checks.positive(value, "height");
            return this;
        }

        /** The top speed in units per simulated second (the server allows at most 20). */
        public Builder speed(double value) {
            this.speed = Checks.positive(value, "speed");
            return this;
        }

        /**
         * The gripper: the body part that collects fruit, how far it reaches beyond the body's
         * radius, and the heights of fruit centres it reaches.
         */
        public Builder gripper(String bodyPart, double reachBeyondRadius, double lowest, double highest) {
            Checks.name(bodyPart, "gripper part");
            Checks.positive(reachBeyondRadius, "gripper reach");
            Checks.nonNegative(lowest, "gripper minHeight");
            Checks.finite(highest, "gripper maxHeight");
            if (highest < lowest) {
                throw new IllegalArgumentException("gripper maxHeight must not be below minHeight (" + lowest
                        + "), was " + highest);
            }
            this.part = bodyPart;
            this.reach = reachBeyondRadius;
            this.minHeight = lowest;
            this.maxHeight = highest;
            return this;
        }

        /** How far (units) and how wide (the full angle, radians, at most 2 pi) the agent perceives. */
        public Builder sight(double rangeUnits, double fieldOfViewRadians) {
            Checks.positive(rangeUnits, "sight range");
            Checks.positive(fieldOfViewRadians, "field of view");
            if (fieldOfViewRadians > 2 * Math.PI) {
                throw new IllegalArgumentException("field of view must be at most 2*pi radians, was "
                        + fieldOfViewRadians);
            }
            this.range = rangeUnits;
            this.fieldOfView = fieldOfViewRadians;
            return this;
        }

        /**
         * The model: a resource next to the agent's class ({@code "Pippin.x3d"}) or absolute
         * ({@code "/models/Pippin.wrl"}); its format follows from the extension: .x3d, .wrl,
         * .gltf or .glb. Its root Transform must be named after the agent.
         */
        public Builder model(String resource) {
            Objects.requireNonNull(resource, "model resource");
            AgentModel.formatOf(resource); // refuses an extension it does not know, naming it
            this.model = resource;
            this.modelName = null;
            return this;
        }

        /**
         * A model whose nodes are named for {@code nameInModel} (its root Transform, and the time
         * sensors that start with that name); they are renamed after the agent when it registers
         * under another name, so that two dwarves can share one model.
         */
        public Builder model(String resource, String nameInModel) {
            model(resource);
            this.modelName = Checks.name(nameInModel, "name in model");
            return this;
        }

        /** Joints of the model to register (Transform nodes the agent will turn). */
        public Builder joints(String... names) {
            for (String name : names) {
                joints.add(Checks.partName(name, "joint"));
            }
            return this;
        }

        /** Time sensors of the model to register (animations the agent will start). */
        public Builder timeSensors(String... names) {
            for (String name : names) {
                timeSensors.add(Checks.partName(name, "time sensor"));
            }
            return this;
        }

        /** The time sensor that animates walking: started while the agent walks, stopped when it stands. */
        public Builder walkAnimation(String timeSensor) {
            this.walkAnimation = Checks.partName(timeSensor, "walk animation");
            timeSensors.add(timeSensor);
            return this;
        }

        /** The time sensor that animates grasping: started with each grasp. */
        public Builder graspAnimation(String timeSensor) {
            this.graspAnimation = Checks.partName(timeSensor, "grasp animation");
            timeSensors.add(timeSensor);
            return this;
        }

        /** Perceive every {@code ticks} ticks (1, the default, is every tick). */
        public Builder perceptionEvery(int ticks) {
            if (ticks < 1) {
                throw new IllegalArgumentException("perceptionEvery must be at least 1 tick, was " + ticks);
            }
            this.perceptionEvery = ticks;
            return this;
        }

        /** The body. */
        public AgentBody build() {
            return new AgentBody(this);
        }
    }

    @Override
    public String toString() {
        List<String> parts = new ArrayList<>();
        parts.add(body.toString());
        if (model != null) {
            parts.add("model " + model);
        }
        parts.add("joints " + joints);
        parts.add("timeSensors " + timeSensors);
        return "AgentBody" + parts;
    }
}
