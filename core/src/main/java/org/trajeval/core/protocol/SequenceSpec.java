package org.trajeval.core.protocol;

import java.util.List;
import java.util.Objects;
import org.trajeval.core.options.RunMetadata;
import org.trajeval.core.options.SettingText;

/**
 * One benchmark sequence of a suite manifest.
 *
 * @param id sequence id, unique in the suite ([A-Za-z0-9._-]+)
 * @param session id of the recording session (one continuous traversal); the split must be the
 *     same for all sequences of a session
 * @param reference path of the reference trajectory, relative to the manifest's folder
 * @param split the split the sequence belongs to
 * @param tags environment tags (e.g. indoor, night), in manifest order
 * @param settings evaluation settings of this sequence's runs on top of the suite's {@code metrics}
 *     (e.g. {@code ref_times}, {@code ref_format}), in manifest order
 * @param about what the data is: domain, simulator, scenario, factor levels, taxonomy ({@link RunMetadata})
 */
public record SequenceSpec(String id, String session, String reference, Split split, List<String> tags,
        List<SettingText> settings, RunMetadata about) {
    /** A sequence without description fields. */
    public SequenceSpec(String id, String session, String reference, Split split, List<String> tags,
            List<SettingText> settings) {
        this(id, session, reference, split, tags, settings, RunMetadata.NONE);
    }

    /** @throws NullPointerException on a missing component */
    public SequenceSpec {
        Objects.requireNonNull(about, "about");
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(session, "session");
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(split, "split");
        tags = List.copyOf(tags);
        settings = List.copyOf(settings);
    }
}
