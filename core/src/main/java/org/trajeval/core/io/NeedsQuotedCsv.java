package org.trajeval.core.io;

/**
 * Internal signal of the fast CSV path: the file has a quote character, so it needs full CSV
 * semantics and is read again with Commons CSV. Never leaves this package.
 */
final class NeedsQuotedCsv extends RuntimeException {
    private static final long serialVersionUID = 1L;

    NeedsQuotedCsv() {
        super("quoted CSV", null, false, false);
    }
}
