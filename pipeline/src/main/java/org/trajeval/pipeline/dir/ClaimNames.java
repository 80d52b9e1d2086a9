package org.trajeval.pipeline.dir;

import java.util.UUID;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Names of the folders a claim prepares in processing/ ({@code .claim-NAME}, see {@link Slot#claim}):
 * one random UUID per service instance followed by a counter ({@code 3f2a...-17}), unique among the
 * processes sharing processing/ as a UUID per claim was, without reading the system's secure random
 * source for every bundle.
 */
final class ClaimNames {
    private final String instance = UUID.randomUUID().toString();
    private final AtomicLong next = new AtomicLong();

    /** @return a name no other claim of any process uses */
    String next() {
        return instance + "-" + next.incrementAndGet();
    }
}
