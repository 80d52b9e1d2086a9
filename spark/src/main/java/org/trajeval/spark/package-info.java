/**
 * trajeval on Apache Spark: {@link org.trajeval.spark.TrajevalSpark#score} scores a table of
 * (reference, estimate) pairs on a cluster, one result row per input row (schema
 * {@link org.trajeval.spark.ResultSchema}); {@link org.trajeval.spark.SparkJob} is the
 * {@code trajeval-spark} command and the {@code spark-submit} entry point. Spark is provided by
 * the cluster; this package depends on trajeval's core only.
 */
package org.trajeval.spark;
