/**
 * The {@code trajeval} command line. Internal: no Java API (the command, its options, its JSON
 * and its exit codes are the interface); in Java use {@link org.trajeval.api}.
 */
package org.trajeval.cli;
