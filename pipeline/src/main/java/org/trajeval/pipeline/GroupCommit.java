package org.trajeval.pipeline;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Commits requests of several threads together (a group commit): a thread that submits while no
 * group is being committed becomes the leader and commits every request queued so far in one call
 * of the group action (its own included); threads that submit meanwhile wait, and the first of them
 * whose request is still open leads the next group. A caller returns only once its own request is
 * complete, so whatever the action guarantees for a request (a report file and its ledger line
 * durable, say) holds when {@link #submit} returns.
 *
 * <p>No thread waits on purpose for others: a group is whatever queued while the previous group was
 * being committed (one request on an idle service, up to one per worker under load).
 *
 * @param <T> a request; the action completes each request of its group ({@link Request#complete} or
 *     {@link Request#fail}), and a request the action leaves open fails with the action's exception
 */
public final class GroupCommit<T extends GroupCommit.Request<?>> {
    private final Consumer<List<T>> action;
    private final List<T> queue = new ArrayList<>();
    private boolean leading;
    private long groups;

    /** @param action commits one group of requests, in the order they were submitted */
    public GroupCommit(Consumer<List<T>> action) {
        this.action = action;
    }

    /** A request and, once its group was committed, its result or failure. */
    public abstract static class Request<R> {
        private R result;
        private RuntimeException failure;
        private volatile boolean done; // written last: a thread that sees it set sees the result

        /** Sets the request's result. */
        public final void complete(R r) {
            result = r;
            done = true;
        }

        /** Fails the request: {@link #submit} throws {@code e} in the submitting thread. */
        public final void fail(RuntimeException e) {
            failure = e;
            done = true;
        }

        /** @return whether the request was completed or failed */
        public final boolean isDone() {
            return done;
        }
    }

    /**
     * Commits the request, in a group with whatever other threads submit meanwhile.
     *
     * @return the request's result
     * @throws RuntimeException the exception the request was failed with
     */
    public <R> R submit(T request) {
        List<T> group;
        boolean interrupted = false;
        synchronized (this) {
            queue.add(request);
            while (leading && !request.isDone()) {
                try {
                    wait();
                } catch (InterruptedException e) {
                    interrupted = true; // the commit is under way: finish it, keep the interrupt
                }
            }
            if (!request.isDone()) {
                leading = true;
                group = new ArrayList<>(queue);
                queue.clear();
                groups++;
            } else {
                group = null;
            }
        }
        if (group != null) {
            commit(group);
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        @SuppressWarnings("unchecked")
        Request<R> r = (Request<R>) request;
        if (r.failure != null) {
            throw r.failure;
        }
        return r.result;
    }

    /** @return how many groups were committed so far (at most the number of requests) */
    public synchronized long groups() {
        return groups;
    }

    /** @return how many requests wait for the group being committed to finish */
    public synchronized int waiting() {
        return queue.size();
    }

    private void commit(List<T> group) {
        RuntimeException thrown = null;
        Error error = null;
        try {
            action.accept(group);
        } catch (RuntimeException e) {
            thrown = e;
        } catch (Error e) {
            error = e;
            thrown = new IllegalStateException("group commit failed: " + e, e);
        } finally {
            synchronized (this) {
                for (T r : group) {
                    if (!r.isDone()) {
                        r.fail(thrown != null ? thrown
                                : new IllegalStateException("group commit left a request open"));
                    }
                }
                leading = false;
                notifyAll();
            }
        }
        if (error != null) {
            throw error;
        }
    }
}
