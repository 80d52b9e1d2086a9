/**
 * The evaluator and its resolved options. Internal: may change in any release; in Java use
 * {@link org.trajeval.api.TrajectoryEvaluator}.
 */
package org.trajeval.core.eval;
