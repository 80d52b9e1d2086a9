/**
 * The versioned reports and their JSON. Public API (see {@link org.trajeval.api}):
 * {@link org.trajeval.core.report.EvaluationReport} with its nested records, and
 * {@link org.trajeval.core.report.ReportJson}. Everything else here is internal.
 */
package org.trajeval.core.report;
