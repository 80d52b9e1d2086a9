package org.trajeval.core.protocol;

import java.util.Objects;

/**
 * The compute budget B of the protocol (lesson section 4). Recorded in the report, and checked run by
 * run when the manifest names a resources table ({@link BudgetCheck}).
 *
 * @param device cpu or gpu
 * @param cores CPU cores the methods were allowed, or {@code null} when not stated
 * @param realTimeFactor smallest real-time factor a run must achieve: the data's duration over the run's wall
 *     time (dimensionless, &gt; 0; 1 = real time, 2 = twice as fast as real time)
 * @param memoryCapMib memory cap (MiB, &gt; 0)
 */
public record Budget(String device, Integer cores, double realTimeFactor, long memoryCapMib) {
    /** @throws IllegalArgumentException on an unknown device or a non-positive figure */
    public Budget {
        Objects.requireNonNull(device, "device");
        if (!device.equals("cpu") && !device.equals("gpu")) {
            throw new IllegalArgumentException("device must be cpu or gpu, got " + device);
        }
        if (cores != null && cores < 1) {
            throw new IllegalArgumentException("cores must be >= 1, got " + cores);
        }
        if (!(realTimeFactor > 0.0) || !Double.isFinite(realTimeFactor)) {
            throw new IllegalArgumentException("real_time_factor must be > 0, got " + realTimeFactor);
        }
        if (memoryCapMib < 1) {
            throw new IllegalArgumentException("memory_cap_mib must be >= 1, got " + memoryCapMib);
        }
    }
}
