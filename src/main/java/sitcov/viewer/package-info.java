/**
 * The live viewer (Swing), opened by {@code view}: a window that steps a run, and with a fault its
 * fault-free twin beside it, while a person watches ({@link sitcov.viewer.ViewerWindow}), and the painter
 * of one run as it stands, sensors included ({@link sitcov.viewer.RunPainter}). It owns the runs it
 * shows; the model never knows it is watched.
 */
package sitcov.viewer;
