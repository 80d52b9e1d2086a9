package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The names of claim folders stay unique within a service and across instances sharing processing/. */
class ClaimNamesTest {
    @Test
    void namesNeverRepeatWithinOrAcrossInstances() throws Exception {
        // two instances (two processes sharing processing/), each named from two threads (two workers' claims)
        ClaimNames a = new ClaimNames();
        ClaimNames b = new ClaimNames();
        Set<String> seen = java.util.concurrent.ConcurrentHashMap.newKeySet();
        Thread[] threads = new Thread[4];
        for (int k = 0; k < threads.length; k++) {
            ClaimNames names = k % 2 == 0 ? a : b;
            threads[k] = new Thread(() -> {
                for (int i = 0; i < 5000; i++) {
                    assertTrue(seen.add(names.next()));
                }
            });
            threads[k].start();
        }
        for (Thread t : threads) {
            t.join();
        }
        assertEquals(20_000, seen.size());
        Set<String> prefixes = new HashSet<>();
        for (String n : seen) {
            prefixes.add(n.substring(0, n.lastIndexOf('-')));
        }
        assertEquals(2, prefixes.size(), "one random prefix per instance");
    }
}
