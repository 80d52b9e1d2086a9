/**
 * The {@code trajeval-pipeline} service. Internal, with its sub-packages: no Java API (the
 * command, its configuration, the report files and events are the interface); in Java use
 * {@link org.trajeval.api}.
 */
package org.trajeval.pipeline;
