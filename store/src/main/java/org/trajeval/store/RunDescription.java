package org.trajeval.store;

/**
 * What a stored run's data is and what it cost (schema v3 columns): the description fields of a
 * suite sequence, run.yaml or Kafka event ({@code org.trajeval.core.options.RunField}) and the
 * measured resources.
 *
 * @param domain sim or real, or null
 * @param scenario scenario id, or null
 * @param simulator simulator, or null
 * @param environment environment type, or null
 * @param modality modality words joined by '+', or null
 * @param groundTruth ground-truth source, or null
 * @param factors factor levels as {@code name=level;name=level}, or null
 * @param wallTimeS measured wall time (s), or null
 * @param peakMemoryMib measured peak memory (MiB), or null
 */
public record RunDescription(String domain, String scenario, String simulator, String environment, String modality,
        String groundTruth, String factors, Double wallTimeS, Double peakMemoryMib) {
    /** Nothing known. */
    public static final RunDescription NONE = new RunDescription(null, null, null, null, null, null, null, null, null);

    /** The columns, in {@link #values()} order. */
    static final String COLUMNS = "domain, scenario, simulator, environment, modality, ground_truth, factors, "
            + "wall_time_s, peak_memory_mib";
    /** Number of columns. */
    static final int COUNT = 9;

    /** @return the column values in {@link #COLUMNS} order */
    Object[] values() {
        return new Object[] {domain, scenario, simulator, environment, modality, groundTruth, factors, wallTimeS,
            peakMemoryMib};
    }
}
