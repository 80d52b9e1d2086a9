/**
 * The evaluator and its options. Public API (see {@link org.trajeval.api}):
 * {@link org.trajeval.core.eval.EvaluationOptions}, {@link org.trajeval.core.eval.Convention},
 * {@link org.trajeval.core.eval.PlanarProjection}. Everything else here is internal (use
 * {@link org.trajeval.api.TrajectoryEvaluator}).
 */
package org.trajeval.core.eval;
