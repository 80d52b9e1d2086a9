/**
 * Version and input errors. Public API (see {@link org.trajeval.api}): {@link org.trajeval.core.Version},
 * {@link org.trajeval.core.InputException}, {@link org.trajeval.core.InputProblem}.
 */
package org.trajeval.core;
