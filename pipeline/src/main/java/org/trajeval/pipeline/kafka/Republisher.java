package org.trajeval.pipeline.kafka;

import java.nio.file.Files;
import java.time.Instant;
import java.util.Comparator;
import java.util.List;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.ledger.LedgerEntry;

/**
 * Report events re-built from the ledger: one per ledger entry (run id, version) whose report
 * file exists, oldest first, marked with the {@code trajeval.republished} header. Used after the
 * broker lost the output topic, and by {@code trajeval-pipeline republish --since}.
 */
public final class Republisher {
    private final Ledger ledger;
    private final ReportStore store;
    private final String topic;

    /**
     * @param ledger the ledger of reported runs
     * @param store where the report files are
     * @param topic the output topic
     */
    public Republisher(Ledger ledger, ReportStore store, String topic) {
        this.ledger = ledger;
        this.store = store;
        this.topic = topic;
    }

    /** @return the ledger entries reported at or after {@code since}, oldest first (the ledger read up to date) */
    public List<LedgerEntry> entriesSince(Instant since) {
        ledger.locked(view -> null);
        return ledger.entries().stream().filter(e -> e.timeMillis() >= since.toEpochMilli())
                .sorted(Comparator.comparingLong(LedgerEntry::timeMillis)).toList();
    }

    /** @return the report event of a ledger entry, or null when its report file is gone */
    public ProducerRecord<String, String> event(LedgerEntry e) {
        var file = store.reportFile(e.runId(), e.version());
        return Files.isRegularFile(file) ? ReportEvents.of(topic, file, e.source(), true) : null;
    }
}
