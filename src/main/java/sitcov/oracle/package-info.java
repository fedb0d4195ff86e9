/**
 * The accident oracle: the {@link sitcov.oracle.AccidentDetector} stepped after every vehicle moved,
 * its accident events and blame rules, and the {@link sitcov.oracle.RunResult} of a run.
 */
package sitcov.oracle;
