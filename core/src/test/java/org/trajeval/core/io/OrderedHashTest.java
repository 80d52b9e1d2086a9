package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/** The in-order SHA-256 of blocks offered in any order by several threads ({@link OrderedHash}). */
class OrderedHashTest {
    @Test
    void blocksOfferedInAnyOrderGiveTheSha256OfTheirBytesInFileOrder() throws Exception {
        Random rnd = new Random(11);
        byte[][] blocks = new byte[40][];
        MessageDigest whole = MessageDigest.getInstance("SHA-256"); // the reference: every byte in order, one pass
        for (int k = 0; k < blocks.length; k++) {
            blocks[k] = new byte[1 + rnd.nextInt(300)];
            rnd.nextBytes(blocks[k]);
            whole.update(blocks[k]);
        }
        String expected = HexFormat.of().formatHex(whole.digest());
        ExecutorService pool = Executors.newFixedThreadPool(3);
        try {
            for (int round = 0; round < 20; round++) {
                List<Integer> order = new ArrayList<>();
                for (int k = 0; k < blocks.length; k++) {
                    order.add(k);
                }
                Collections.shuffle(order, rnd);
                OrderedHash hash = new OrderedHash(blocks.length, blocks.length); // no waiting: any order
                AtomicInteger hashed = new AtomicInteger();
                List<Future<?>> offers = new ArrayList<>();
                for (int k : order) {
                    byte[] b = java.util.Arrays.copyOf(blocks[k], blocks[k].length + 5); // bytes past the length are not hashed
                    offers.add(pool.submit(() -> hash.offer(k, b, blocks[k].length, hashed::incrementAndGet)));
                }
                for (Future<?> f : offers) {
                    f.get(10, TimeUnit.SECONDS);
                }
                assertEquals(blocks.length, hashed.get(), "every block's whenHashed ran once");
                assertEquals(expected, hash.digest());
            }
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void readerOfABlockBeyondTheWindowWaitsUntilTheHashCatchesUp() throws Exception {
        OrderedHash hash = new OrderedHash(4, 2);
        assertTrue(hash.awaitTurn(0));
        assertTrue(hash.awaitTurn(1));
        CountDownLatch admitted = new CountDownLatch(1);
        Thread reader = new Thread(() -> {
            if (hash.awaitTurn(2)) { // blocks 0 and 1 unhashed: the window of 2 is full
                admitted.countDown();
            }
        });
        reader.start();
        assertFalse(admitted.await(200, TimeUnit.MILLISECONDS), "block 2 was let in ahead of the window");
        hash.offer(1, new byte[] {1}, 1, () -> { });
        assertFalse(admitted.await(200, TimeUnit.MILLISECONDS), "block 1 is not hashed before block 0");
        hash.offer(0, new byte[] {0}, 1, () -> { });
        assertTrue(admitted.await(10, TimeUnit.SECONDS));
        reader.join();
        assertNull(hash.digest(), "blocks 2 and 3 are not hashed yet");
    }

    @Test
    void abandoningWakesAWaitingReaderAndGivesNoDigest() throws Exception {
        OrderedHash hash = new OrderedHash(3, 1);
        AtomicInteger result = new AtomicInteger(-1);
        Thread reader = new Thread(() -> result.set(hash.awaitTurn(2) ? 1 : 0));
        reader.start();
        for (int k = 0; k < 10_000 && reader.getState() != Thread.State.WAITING; k++) {
            Thread.sleep(1); // abandoned only once the reader waits, so the test needs abandon's wake-up
        }
        assertEquals(Thread.State.WAITING, reader.getState(), "block 2 waits for blocks 0 and 1");
        hash.abandon();
        reader.join(10_000);
        assertFalse(reader.isAlive());
        assertEquals(0, result.get(), "told the read was abandoned");
        hash.offer(0, new byte[] {0}, 1, () -> { });
        assertNull(hash.digest());
    }
}
