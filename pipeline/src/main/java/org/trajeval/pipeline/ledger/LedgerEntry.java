package org.trajeval.pipeline.ledger;

import java.util.Objects;

/**
 * One reported run in the ledger.
 *
 * @param runId run id
 * @param contentHash the run's content hash (SHA-256 hex)
 * @param version the report version this content got (1, 2, ...)
 * @param timeMillis when it was reported (ms since the epoch, UTC)
 * @param source where the run came from (bundle name, topic-partition@offset)
 */
public record LedgerEntry(String runId, String contentHash, int version, long timeMillis, String source) {
    /** @throws IllegalArgumentException on a field that would break the line format */
    public LedgerEntry {
        Objects.requireNonNull(runId, "runId");
        Objects.requireNonNull(contentHash, "contentHash");
        if (version < 1) {
            throw new IllegalArgumentException("version must be >= 1, got " + version);
        }
        if (runId.indexOf('\t') >= 0 || runId.indexOf('\n') >= 0 || contentHash.indexOf('\t') >= 0) {
            throw new IllegalArgumentException("run id and hash must not hold tabs or newlines");
        }
        source = source == null ? "" : source.replace('\t', ' ').replace('\n', ' ').replace('\r', ' ');
    }

    String toLine() {
        return "R\t" + runId + '\t' + contentHash + '\t' + version + '\t' + timeMillis + '\t' + source + '\n';
    }

    static LedgerEntry parse(String line) {
        String[] f = line.split("\t", -1);
        if (f.length != 6 || !"R".equals(f[0])) {
            return null;
        }
        try {
            return new LedgerEntry(f[1], f[2], Integer.parseInt(f[3]), Long.parseLong(f[4]), f[5]);
        } catch (IllegalArgumentException e) {
            return null;
        }
    }
}
