package org.trajeval.pipeline;

/** Carries a {@link RunFailure} out of the processing of one run. */
public final class StageException extends RuntimeException {
    private static final long serialVersionUID = 1L;
    private final transient RunFailure failure;

    /** @param failure why the run failed */
    public StageException(RunFailure failure, Throwable cause) {
        super(failure.message(), cause);
        this.failure = failure;
    }

    /** @return why the run failed */
    public RunFailure failure() {
        return failure;
    }
}
