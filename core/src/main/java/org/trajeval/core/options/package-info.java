/**
 * The one table of evaluation settings and its resolver. The settings' keys and values are public
 * (see {@link org.trajeval.api}); the classes here are internal and may change in any release.
 */
package org.trajeval.core.options;
