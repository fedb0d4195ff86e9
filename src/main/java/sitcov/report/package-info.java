/**
 * Reports: CSV, PNG rendering (Java2D, headless), plots, the HTML report. Knows the experiment and
 * everything below it; nothing below knows it.
 */
package sitcov.report;
