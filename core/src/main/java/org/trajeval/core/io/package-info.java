/**
 * Readers and writers of trajectory files (Commons CSV stays in this package). Internal: may change in any release; the public API is {@link org.trajeval.api}.
 */
package org.trajeval.core.io;
