package org.trajeval.pipeline.bundle;

/**
 * Size limits that keep a bad bundle from exhausting the disk or the memory.
 *
 * @param maxFileBytes largest trajectory or manifest file (bytes), > 0
 * @param maxUnzippedBytes largest total of a zip's extracted files (bytes), > 0
 * @param maxZipEntries most entries a zip may hold, > 0
 * @param maxCompressionRatio largest ratio extracted bytes / zip file bytes (a zip bomb exceeds it), > 1
 */
public record BundleLimits(long maxFileBytes, long maxUnzippedBytes, int maxZipEntries, double maxCompressionRatio) {
    /** 256 MiB per file, 1 GiB per zip, 1000 entries, ratio 200. */
    public static final BundleLimits DEFAULTS = new BundleLimits(256L << 20, 1L << 30, 1000, 200.0);

    /** @throws IllegalArgumentException on a non-positive limit */
    public BundleLimits {
        if (maxFileBytes <= 0 || maxUnzippedBytes <= 0 || maxZipEntries <= 0 || !(maxCompressionRatio > 1.0)) {
            throw new IllegalArgumentException("bundle limits must be positive (ratio > 1), got max_file_bytes="
                    + maxFileBytes + ", max_unzipped_bytes=" + maxUnzippedBytes + ", max_zip_entries="
                    + maxZipEntries + ", max_compression_ratio=" + maxCompressionRatio);
        }
    }
}
