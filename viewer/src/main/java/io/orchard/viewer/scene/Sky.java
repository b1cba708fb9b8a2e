package io.orchard.viewer.scene;

import com.jme3.asset.AssetManager;
import com.jme3.material.Material;
import com.jme3.material.RenderState;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.renderer.Camera;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.scene.Geometry;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.scene.control.AbstractControl;
import com.jme3.scene.shape.Sphere;
import com.jme3.util.BufferUtils;
import java.nio.FloatBuffer;

/**
 * A sky: a dome coloured from a pale horizon to a deeper blue overhead, drawn behind everything
 * and centred on the camera wherever it goes.
 */
public final class Sky {

    /** The colour at the horizon, also the viewport's background. */
    public static final ColorRGBA HORIZON = Palette.srgb(0.78f, 0.86f, 0.93f);
    private static final ColorRGBA ZENITH = Palette.srgb(0.33f, 0.55f, 0.85f);
    private static final ColorRGBA BELOW = Palette.srgb(0.55f, 0.62f, 0.55f);

    private Sky() {
    }

    /** The sky dome, following {@code camera}. */
    public static Geometry build(AssetManager assets, Camera camera) {
        Sphere sphere = new Sphere(24, 32, 10f, false, true);
        FloatBuffer positions = sphere.getFloatBuffer(VertexBuffer.Type.Position);
        int count = positions.limit() / 3;
        FloatBuffer colors = BufferUtils.createFloatBuffer(count * 4);
        ColorRGBA color = new ColorRGBA();
        for (int i = 0; i < count; i++) {
            // The sphere's axis is z; its z is the sky's up.
            float up = positions.get(i * 3 + 2) / 10f;
            if (up >= 0) {
                color.interpolateLocal(HORIZON, ZENITH, FastMath.sqrt(up));
            } else {
                color.interpolateLocal(HORIZON, BELOW, Math.min(1, -up * 4));
            }
            colors.put(color.r).put(color.g).put(color.b).put(1f);
        }
        colors.flip();
        sphere.setBuffer(VertexBuffer.Type.Color, 4, colors);
        Geometry dome = new Geometry("sky", sphere);
        dome.rotate(-FastMath.HALF_PI, 0, 0);
        Material material = new Material(assets, "Common/MatDefs/Misc/Unshaded.j3md");
        material.setBoolean("VertexColor", true);
        material.getAdditionalRenderState().setFaceCullMode(RenderState.FaceCullMode.Off);
        material.getAdditionalRenderState().setDepthWrite(false);
        dome.setMaterial(material);
        dome.setQueueBucket(RenderQueue.Bucket.Sky);
        dome.setCullHint(Spatial.CullHint.Never);
        dome.setShadowMode(RenderQueue.ShadowMode.Off);
        dome.addControl(new FollowCamera(camera));
        return dome;
    }

    /** Keeps the dome centred on the camera. */
    private static final class FollowCamera extends AbstractControl {

        private final Camera camera;

        FollowCamera(Camera camera) {
            this.camera = camera;
        }

        @Override
        protected void controlUpdate(float tpf) {
            spatial.setLocalTranslation(camera.getLocation());
        }

        @Override
        protected void controlRender(RenderManager renderManager, ViewPort viewPort) {
        }
    }
}
