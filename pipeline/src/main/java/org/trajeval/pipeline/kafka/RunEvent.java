package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Set;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingValues;
import org.trajeval.pipeline.bundle.RunFields;
import org.trajeval.pipeline.RunMetadata;

/**
 * A run event from the input topic (JSON), either pointing at a bundle or carrying both
 * trajectories inline:
 * <pre>
 * {"run_id": "r0412", "robot_id": "bot-3", "bundle": "night-07/r0412.zip"}
 * {"run_id": "r0414", "robot_id": "bot-3", "bundle": "night-07/r0414.mcap"}   (a bare bag: bags.metrics of the configuration)
 * {"run_id": "r0413", "robot_id": "bot-3", "sequence": "hall", "method": "orb", "seed": 1,
 *  "site": "hamburg", "software_version": "2.10", "tags": {"shift": "night"},
 *  "reference": {"file_name": "gt.csv", "data": "t,x,y,yaw\n0,0,0,0\n..."},
 *  "estimate":  {"file_name": "est.csv", "data": "..."},
 *  "metrics": {"alignment": "se2"}}
 * </pre>
 *
 * @param metadata run identity (for a bundle event: checked against the bundle's run.yaml)
 * @param bundle bundle location relative to the bundle base, or {@code null}
 * @param reference inline reference, or {@code null}
 * @param estimate inline estimate, or {@code null}
 * @param settings checked settings of an inline event (a bundle event takes its run.yaml's)
 */
public record RunEvent(RunMetadata metadata, String bundle, Inline reference, Inline estimate, SettingValues settings) {
    private static final ObjectMapper JSON = org.trajeval.core.io.StrictMappers.json();
    private static final Set<String> KEYS = RunFields.keysWith("bundle",
            "reference", "estimate", "metrics");
    private static final Pattern FILE_NAME = Pattern.compile("[A-Za-z0-9_-][A-Za-z0-9._-]{0,100}");

    /**
     * An inline trajectory.
     *
     * @param fileName simple file name (the extension guides format detection), e.g. gt.csv, est.txt
     * @param data the file's text
     */
    public record Inline(String fileName, String data) {
    }

    /** @throws InputException naming the field when the event is malformed */
    public static RunEvent parse(String json, String source) {
        JsonNode root;
        try {
            root = json == null ? null : JSON.readTree(json);
        } catch (JsonProcessingException e) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "a run event must be a JSON object: " + e.getOriginalMessage(), null, e);
        }
        if (root == null || !root.isObject()) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "a run event must be a JSON object with run_id and bundle (or reference and estimate)",
                    json == null ? "null" : json.length() > 40 ? json.substring(0, 40) : json);
        }
        RunFields.requireKnown(root, KEYS, "", source);
        RunMetadata metadata = RunFields.metadata(root, source);
        String bundle = RunFields.text(root, "bundle", source, false);
        Inline ref = inline(root, "reference", source);
        Inline est = inline(root, "estimate", source);
        if ((bundle == null) == (ref == null || est == null)) {
            throw new InputException(source, 0, "bundle", InputProblem.INVALID_CONFIGURATION,
                    "a run event needs either bundle or both reference and estimate", null);
        }
        if (bundle != null && root.hasNonNull("metrics")) {
            throw new InputException(source, 0, "metrics", InputProblem.INVALID_CONFIGURATION,
                    "a bundle event takes its settings from the bundle's run.yaml (a bare bag's from the service "
                            + "configuration's bags.metrics); put metrics there", null);
        }
        for (String label : new String[] {"site", "software_version", "tags"}) {
            if (bundle != null && root.hasNonNull(label)) {
                throw new InputException(source, 0, label, InputProblem.INVALID_CONFIGURATION,
                        "a bundle event takes its labels from the bundle's run.yaml; put " + label + " there", null);
            }
        }
        SettingValues settings = RunFields.settings(root, source);
        for (Setting s : new Setting[] {Setting.REF_TIMES, Setting.EST_TIMES}) {
            if (settings.has(s)) {
                throw new InputException(source, 0, settings.where(s), InputProblem.INVALID_CONFIGURATION,
                        "'" + settings.where(s) + "' names a file, which an inline event cannot carry; send a bundle",
                        String.valueOf(settings.get(s)));
            }
        }
        return new RunEvent(metadata, bundle, ref, est, settings);
    }

    private static Inline inline(JsonNode root, String key, String source) {
        JsonNode n = root.get(key);
        if (n == null || n.isNull()) {
            return null;
        }
        if (!n.isObject() || !n.hasNonNull("data") || !n.get("data").isTextual()) {
            throw new InputException(source, 0, key, InputProblem.INVALID_CONFIGURATION,
                    key + " must be an object {\"file_name\": ..., \"data\": \"<file text>\"}", n.toString());
        }
        String name = n.hasNonNull("file_name") ? n.get("file_name").asText() : key + ".csv";
        if (!FILE_NAME.matcher(name).matches()) {
            throw new InputException(source, 0, key + ".file_name", InputProblem.PATH_ESCAPES,
                    key + ".file_name must be a plain file name (A-Z a-z 0-9 . _ -)", name);
        }
        return new Inline(name, n.get("data").asText());
    }
}
