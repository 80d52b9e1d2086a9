/**
 * ATE, RPE and drift. Internal, except the option types {@link org.trajeval.core.metric.DriftOptions},
 * {@link org.trajeval.core.metric.PairSelection}, {@link org.trajeval.core.metric.PairsFrom} and
 * {@link org.trajeval.core.metric.RpeUnit} (public API, see {@link org.trajeval.api}).
 */
package org.trajeval.core.metric;
