// Runs LCM's lcm-spy (lcm.spy.Spy, the class Debian's lcm-spy script starts) in this JVM and
// watches its channel table until a channel shows a decoded type: it prints
// "lcm-spy: CHANNEL decoded as TYPE (N messages, U undecodable)" and the window's title, saves a screenshot
// of the window (PNG) and exits 0; when the timeout passes first it still saves the
// screenshot, says what the table held and exits 1. lcm-spy shows "?" (or nothing) as the
// type of a message whose fingerprint no class on the classpath matches, so a decoded type
// name proves the jar's classes decode what the cell publishes.
//
//   java -cp lcm.jar:cosmos_lcm_types.jar:. LcmSpyProbe OUT.png TIMEOUT_S CHANNEL [lcm-spy args]

import java.awt.Component;
import java.awt.Container;
import java.awt.Frame;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.File;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.JTable;
import javax.swing.SwingUtilities;
import javax.swing.table.TableModel;

public class LcmSpyProbe {
  private static JTable findTable(Component component) {
    if (component instanceof JTable) return (JTable) component;
    if (component instanceof Container) {
      for (Component child : ((Container) component).getComponents()) {
        JTable table = findTable(child);
        if (table != null) return table;
      }
    }
    return null;
  }

  private static int column(TableModel model, String name) {
    for (int c = 0; c < model.getColumnCount(); ++c)
      if (model.getColumnName(c).trim().equalsIgnoreCase(name)) return c;
    return -1;
  }

  // "TYPE (N messages)" for `channel` once its type is decoded, else null; `seen` gets the table.
  private static String decodedType(String channel, StringBuilder seen) {
    for (Frame frame : Frame.getFrames()) {
      JTable table = findTable(frame);
      if (table == null) continue;
      TableModel model = table.getModel();
      int channelColumn = column(model, "Channel");
      int typeColumn = column(model, "Type");
      int countColumn = column(model, "Num Msgs");
      int undecodableColumn = column(model, "Undecodable");
      if (channelColumn < 0 || typeColumn < 0) continue;
      for (int row = 0; row < model.getRowCount(); ++row) {
        String name = String.valueOf(model.getValueAt(row, channelColumn));
        String type = String.valueOf(model.getValueAt(row, typeColumn));
        seen.append(name).append('=').append(type).append(' ');
        if (name.equals(channel) && !type.isEmpty() && !type.equals("?") && !type.equals("null")) {
          String count = countColumn < 0 ? "?" : String.valueOf(model.getValueAt(row, countColumn));
          String undecodable = undecodableColumn < 0 ? "?"
              : String.valueOf(model.getValueAt(row, undecodableColumn));
          return type + " (" + count + " messages, " + undecodable + " undecodable)";
        }
      }
    }
    return null;
  }

  private static void screenshot(String path) throws Exception {
    AtomicReference<Rectangle> bounds = new AtomicReference<>();
    AtomicReference<String> title = new AtomicReference<>("");
    SwingUtilities.invokeAndWait(() -> {
      for (Frame frame : Frame.getFrames()) {
        if (frame.isShowing() && findTable(frame) != null) {
          bounds.set(frame.getBounds());
          title.set(frame.getTitle());
        }
      }
    });
    Rectangle area = bounds.get() != null ? bounds.get()
        : new Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize());
    BufferedImage image = new Robot().createScreenCapture(area);
    ImageIO.write(image, "png", new File(path));
    System.out.println("lcm-spy: window '" + title.get() + "' " + area.width + "x" + area.height
        + " saved as " + path);
  }

  public static void main(String[] args) throws Exception {
    if (args.length < 3) {
      System.err.println("usage: LcmSpyProbe OUT.png TIMEOUT_S CHANNEL [lcm-spy args]");
      System.exit(2);
    }
    String png = args[0];
    long deadline = System.nanoTime() + (long) (Double.parseDouble(args[1]) * 1e9);
    String channel = args[2];
    lcm.spy.Spy.main(Arrays.copyOfRange(args, 3, args.length));
    System.out.println("lcm-spy: started");
    String decoded = null;
    StringBuilder seen = new StringBuilder();
    while (decoded == null && System.nanoTime() < deadline) {
      Thread.sleep(200);
      AtomicReference<String> result = new AtomicReference<>();
      StringBuilder table = new StringBuilder();
      SwingUtilities.invokeAndWait(() -> result.set(decodedType(channel, table)));
      decoded = result.get();
      seen = table;
    }
    // A moment more, so the screenshot shows the repainted table.
    Thread.sleep(1000);
    screenshot(png);
    if (decoded == null) {
      System.out.println("lcm-spy: " + channel + " not decoded in time; table: " + seen);
      System.exit(1);
    }
    System.out.println("lcm-spy: " + channel + " decoded as " + decoded);
    System.exit(0);
  }
}
