package org.trajeval.core.options;

import java.util.ArrayList;
import java.util.List;

/**
 * The table of per-run description fields shared by every front end: a suite manifest's sequence,
 * a bundle's {@code run.yaml} and a Kafka run event. They describe where a run's data came from
 * (simulation or reality, which scenario, which controlled factor levels) and how it was recorded
 * (environment, sensing modality, ground-truth source). {@link RunMetadata#parse} checks them;
 * the evaluation settings are in {@link Setting}.
 */
public enum RunField {
    DOMAIN("domain", "sim|real", "Where the data comes from: a simulator (sim) or the real world (real). "
            + "Sequences of both give the domain-gap section (L_real - L_sim per method)."),
    SIMULATOR("simulator", "NAME", "Simulator that produced a sim sequence (free word: gazebo, webots, carla, "
            + "airsim, ...); needs domain sim."),
    SCENARIO("scenario", "ID", "Route or situation the sequence reproduces; a sim and a real sequence with the "
            + "same scenario are paired in the domain gap."),
    FACTORS("factors", "{NAME: NUMBER, ...}", "Controlled factor levels of the sequence (e.g. "
            + "obstacle_density: 0.4); each factor gives a stress sweep."),
    ENVIRONMENT("environment", "WORD", "Environment type (indoor, campus, urban, warehouse, field, ...); a slice "
            + "of the report."),
    MODALITY("modality", "WORD|[WORD, ...]", "Sensing modality (wheel, imu, lidar, rgbd, stereo, gnss, ...); "
            + "several are joined with '+' (stereo+imu); a slice of the report."),
    GROUND_TRUTH("ground_truth", "mocap|laser_tracker|rtk_ins|map_alignment|simulator", "Source of the reference "
            + "poses; a slice of the report.");

    private final String key;
    private final String values;
    private final String help;

    RunField(String key, String values, String help) {
        this.key = key;
        this.values = values;
        this.help = help;
    }

    /** @return the key in files and events */
    public String key() {
        return key;
    }

    /** @return the allowed words ({@code a|b}) or the value's label */
    public String allowed() {
        return values;
    }

    /** @return the help text */
    public String help() {
        return help;
    }

    /** @return the field with this key, or {@code null} */
    public static RunField fromKey(String key) {
        for (RunField f : values()) {
            if (f.key.equals(key)) {
                return f;
            }
        }
        return null;
    }

    /** @return every key, in table order */
    public static List<String> keys() {
        List<String> out = new ArrayList<>();
        for (RunField f : values()) {
            out.add(f.key);
        }
        return out;
    }
}
