package org.trajeval.pipeline.bundle;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.SettingValues;
import org.trajeval.pipeline.RunMetadata;

/**
 * A bundle's {@code run.yaml}:
 * <pre>
 * run_id: r0412          # required; names reports/r0412.json
 * robot_id: bot-3
 * sequence: warehouse-a
 * method: orb-slam3
 * seed: 7
 * reference: truth.csv   # required, relative to the bundle
 * estimate: estimate.csv # required, relative to the bundle
 * metrics:               # optional: any key of the settings table (org.trajeval.core.options.Setting)
 *   alignment: se2       #   paths (ref_times, est_times) are relative to the bundle and stay inside it
 * plot: true             # optional (default false): eval --plot's figures in reports/RUN_ID.plots/
 * </pre>
 * Unknown keys are refused (a typo must not silently change a metric).
 *
 * @param metadata the run's identity
 * @param reference the reference path as written
 * @param estimate the estimate path as written
 * @param settings the metric settings
 * @param plot true to draw the run's figures beside its report
 */
public record RunManifest(RunMetadata metadata, String reference, String estimate, SettingValues settings,
        boolean plot) {
    /** Name of the manifest file in a bundle. */
    public static final String FILE_NAME = "run.yaml";

    private static final ObjectMapper YAML = org.trajeval.core.io.StrictMappers.yaml();
    private static final Set<String> KEYS = RunFields.keysWith("reference",
            "estimate", "metrics", "plot");

    /**
     * Reads and checks a manifest file.
     *
     * @param file the run.yaml
     * @param source how to name it in messages
     * @param maxBytes largest accepted size (bytes)
     * @throws InputException naming the field and what was expected
     */
    public static RunManifest read(Path file, String source, long maxBytes) {
        SafePaths.requireRegularFile(file, source, FILE_NAME, FILE_NAME, maxBytes);
        JsonNode root;
        try {
            String text = org.trajeval.core.io.TextFiles.readUtf8(file, FILE_NAME, maxBytes);
            JsonNode plain = PlainRunYaml.read(text);
            root = plain != null ? plain : YAML.readTree(text);
        } catch (JsonProcessingException e) {
            JsonLocation loc = e.getLocation();
            throw new InputException(source, loc == null ? 0 : Math.max(0, loc.getLineNr()), null,
                    InputProblem.INVALID_CONFIGURATION, "run.yaml must be valid YAML: " + e.getOriginalMessage(),
                    null, e);
        }
        return parse(root, source);
    }

    /** @return the manifest in a parsed YAML or JSON tree */
    static RunManifest parse(JsonNode root, String source) {
        if (root == null || !root.isObject()) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "run.yaml must be a mapping of run_id, reference, estimate, ...", null);
        }
        RunFields.requireKnown(root, KEYS, "", source);
        RunMetadata metadata = RunFields.metadata(root, source);
        SettingValues settings = RunFields.settings(root, source);
        return new RunManifest(metadata, RunFields.text(root, "reference", source, true),
                RunFields.text(root, "estimate", source, true), settings, RunFields.plot(root, source));
    }
}
