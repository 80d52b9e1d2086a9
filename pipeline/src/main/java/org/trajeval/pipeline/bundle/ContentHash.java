package org.trajeval.pipeline.bundle;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import org.trajeval.pipeline.RunJob;

/**
 * SHA-256 fingerprints of a run: each input file, and the run's content hash over its identity,
 * settings and both files. Two runs with the same content hash are the same run.
 *
 * @param reference SHA-256 of the reference file, lower-case hex
 * @param estimate SHA-256 of the estimate file, lower-case hex
 * @param content SHA-256 of "run id, robot, sequence, method, seed, settings, reference hash, estimate hash"
 *     and, when the run has any, its fleet labels (site, software_version, tags)
 */
public record ContentHash(String reference, String estimate, String content) {

    /** @return the fingerprints of a run (reads both files once, streaming) */
    public static ContentHash of(RunJob job) {
        return of(job, null, null);
    }

    /**
     * @param referenceSha256 SHA-256 of the reference file's bytes (lower-case hex) taken while it was
     *     read for scoring, or null to read the file for it here
     * @param estimateSha256 the same for the estimate file
     * @return the fingerprints of a run, the same as {@link #of(RunJob)} when the given hashes are the files'
     */
    public static ContentHash of(RunJob job, String referenceSha256, String estimateSha256) {
        String ref = referenceSha256 != null ? referenceSha256 : ofFile(job.reference());
        String est = estimateSha256 != null ? estimateSha256
                : job.estimate().equals(job.reference()) ? ref : ofFile(job.estimate()); // a bag: read once
        var m = job.metadata();
        String settings = job.settings().canonical();
        if (job.folder() != null) {
            // a times file named by the settings is an input too: its bytes change the run
            for (org.trajeval.core.options.Setting t : new org.trajeval.core.options.Setting[] {
                org.trajeval.core.options.Setting.REF_TIMES, org.trajeval.core.options.Setting.EST_TIMES}) {
                if (job.settings().has(t)) {
                    settings += ";" + t.key() + "_sha256=" + ofFile(job.folder().resolve((String) job.settings().get(t)));
                }
            }
        }
        String identity = String.join("\n", m.runId(), String.valueOf(m.robotId()), String.valueOf(m.sequence()),
                String.valueOf(m.method()), String.valueOf(m.seed()), settings, ref, est);
        if (!m.labels().isEmpty()) {
            // the same run under another software version is another result; without labels the hash is
            // what it was before labels existed, so ledgers of earlier versions still recognise their runs
            identity += "\n" + m.labels().canonical();
        }
        if (!m.about().equals(org.trajeval.core.options.RunMetadata.NONE) || m.resources() != null) {
            // the description and the measured cost are part of the result (a sim run is not its real twin);
            // absent, the hash is what it was before they existed
            identity += "\n" + m.about() + "\n" + m.resources();
        }
        return new ContentHash(ref, est, hex(digest().digest(identity.getBytes(StandardCharsets.UTF_8))));
    }

    /** @return SHA-256 of the file's bytes, lower-case hex */
    public static String ofFile(Path file) {
        MessageDigest d = digest();
        byte[] buf = new byte[64 * 1024];
        try (InputStream in = Files.newInputStream(file)) {
            for (int n; (n = in.read(buf)) > 0; ) {
                d.update(buf, 0, n);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not read " + file + ": " + e.getMessage(), e);
        }
        return hex(d.digest());
    }

    private static MessageDigest digest() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }

    private static String hex(byte[] b) {
        return HexFormat.of().formatHex(b);
    }
}
