package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** Leader and followers of a group commit: who commits what, and which exception reaches whom. */
class GroupCommitTest {
    private static final class Req extends GroupCommit.Request<String> {
        final String name;

        Req(String name) {
            this.name = name;
        }
    }

    @Test
    void requestsThatArriveDuringACommitAreCommittedTogetherInTheNextGroup() throws Exception {
        int followers = 5;
        CountDownLatch firstGroupStarted = new CountDownLatch(1);
        List<List<String>> groups = Collections.synchronizedList(new ArrayList<>());
        GroupCommit<Req>[] gc = new GroupCommit[1];
        gc[0] = new GroupCommit<>(group -> {
            groups.add(group.stream().map(r -> r.name).toList());
            if (groups.size() == 1) {
                firstGroupStarted.countDown();
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
                while (gc[0].waiting() < followers && System.nanoTime() < until) {
                    Thread.onSpinWait(); // hold the first group until every follower has queued
                }
            }
            group.forEach(r -> r.complete("done " + r.name));
        });
        ExecutorService pool = Executors.newFixedThreadPool(followers + 1);
        try {
            Future<String> first = pool.submit(() -> gc[0].<String>submit(new Req("first")));
            assertTrue(firstGroupStarted.await(30, TimeUnit.SECONDS));
            List<Future<String>> rest = new ArrayList<>();
            for (int i = 0; i < followers; i++) {
                String name = "f" + i;
                rest.add(pool.submit(() -> gc[0].<String>submit(new Req(name))));
            }
            assertEquals("done first", first.get(30, TimeUnit.SECONDS));
            for (int i = 0; i < followers; i++) {
                assertEquals("done f" + i, rest.get(i).get(30, TimeUnit.SECONDS));
            }
        } finally {
            pool.shutdownNow();
        }
        // the first group held only its leader; every follower queued meanwhile went into one second group
        assertEquals(2, groups.size());
        assertEquals(List.of("first"), groups.get(0));
        assertEquals(followers, groups.get(1).size());
        assertEquals(2, gc[0].groups());
    }

    @Test
    void aFailedRequestThrowsItsOwnExceptionAndTheOthersOfItsGroupSucceed() {
        IllegalStateException bad = new IllegalStateException("bad one");
        GroupCommit<Req> gc = new GroupCommit<>(group -> group.forEach(r -> {
            if (r.name.equals("bad")) {
                r.fail(bad);
            } else {
                r.complete("ok");
            }
        }));
        assertSame(bad, assertThrows(IllegalStateException.class, () -> gc.submit(new Req("bad"))));
        assertEquals("ok", gc.<String>submit(new Req("good")));
    }

    @Test
    void anActionThatThrowsFailsEveryOpenRequestOfItsGroupWithThatException() {
        java.io.UncheckedIOException disk = new java.io.UncheckedIOException(new java.io.IOException("No space left"));
        GroupCommit<Req> gc = new GroupCommit<>(group -> {
            throw disk;
        });
        assertSame(disk, assertThrows(java.io.UncheckedIOException.class, () -> gc.submit(new Req("a"))));
        // the next group is led again (leadership was released)
        assertSame(disk, assertThrows(java.io.UncheckedIOException.class, () -> gc.submit(new Req("b"))));
        assertEquals(2, gc.groups());
    }
}
