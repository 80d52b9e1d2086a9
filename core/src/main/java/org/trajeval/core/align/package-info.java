/**
 * Alignment models (EJML stays in this package). Internal, except the option type
 * {@link org.trajeval.core.align.AlignmentModel} (public API, see {@link org.trajeval.api}).
 */
package org.trajeval.core.align;
